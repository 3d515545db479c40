"""Geometry of the part program: frames, planes, circles, polar coordinates, tool offsets."""
