"""Widgets shared by the operating areas (one widget per module)."""
