"""`python -m nck` runs the headless command line."""

from nck.cli import main

raise SystemExit(main())
