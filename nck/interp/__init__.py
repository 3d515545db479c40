"""The interpreter: programs, variables, control flow, canonical command output."""
