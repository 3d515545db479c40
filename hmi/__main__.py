"""``python -m hmi``: the same as the ``hmi`` console script."""

from __future__ import annotations

import sys

from hmi.app import main

sys.exit(main())
