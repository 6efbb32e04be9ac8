"""``python -m isocsg.cli``: the same as the ``isocsg`` console script."""

import sys

from . import main

sys.exit(main())
