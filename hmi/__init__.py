"""The terminal HMI: SINUMERIK Operate on a PC keyboard, talking to the NCK."""
