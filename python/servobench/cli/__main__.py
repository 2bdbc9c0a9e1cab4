"""``python -m servobench.cli``: the command line (as ``python -m servobench``)."""

import sys

from . import main


sys.exit(main())
