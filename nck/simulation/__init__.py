"""Material-removal simulation of a milling program: blank, Z-map, swept tool, events.

Pure and deterministic (numpy, no clock, no threads). :func:`nck.simulation.run.simulate`
runs the program as AUTO runs it (the kernel's headless run, so the alarms, the blocks they
stop at and the machining time are the run's own) and sweeps the active tool along every
executed motion through a height field over the blank.
"""
