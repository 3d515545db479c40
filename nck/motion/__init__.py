"""Motion: planner, interpolator (IPO cycle), axis and drive model, monitoring, JOG, referencing."""
