"""Durations of the simulated control as the panel writes them (runtimes, alarm times, the
simulation's machining time): hours, minutes and seconds."""

from __future__ import annotations


def clock(seconds: float, decimals: int = 0) -> str:
    """``hh:mm:ss`` (with ``decimals`` places of the second: ``hh:mm:ss.cc``), rounded;
    a negative duration counts as 0."""
    scale = 10 ** decimals
    ticks = int(round(max(seconds, 0.0) * scale))
    whole, fraction = divmod(ticks, scale)
    text = f"{whole // 3600:02d}:{whole % 3600 // 60:02d}:{whole % 60:02d}"
    return f"{text}.{fraction:0{decimals}d}" if decimals else text


def short_clock(seconds: float) -> str:
    """``m:ss.s`` under an hour (a simulation of a few minutes reads ``2:05.3``), from an hour
    on ``h:mm:ss.s`` (a CAM program's hours, not ``1005:09.2`` minutes)."""
    tenths = int(round(max(seconds, 0.0) * 10))
    whole, tenth = divmod(tenths, 10)
    hours, rest = divmod(whole, 3600)
    minutes, secs = divmod(rest, 60)
    if hours:
        return f"{hours}:{minutes:02d}:{secs:02d}.{tenth}"
    return f"{minutes}:{secs:02d}.{tenth}"
