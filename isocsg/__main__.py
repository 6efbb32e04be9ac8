"""``python -m isocsg``: the same as the ``isocsg`` console script."""

import sys

from .cli import main

sys.exit(main())
