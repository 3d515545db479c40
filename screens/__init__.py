"""One module per operating area of the HMI."""
