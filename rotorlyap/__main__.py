"""``python -m rotorlyap``: see :mod:`rotorlyap.cli`."""

import sys

from .cli import main

sys.exit(main())
