"""The simulated NCK: a pure, deterministic kernel.

Nothing in this package imports a UI library, reads the wall clock or starts a
thread. Time advances only through the kernel's own tick/step calls.
"""

__version__ = "0.1.0"
