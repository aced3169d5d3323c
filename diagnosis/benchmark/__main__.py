"""``python -m diagnosis.benchmark``: the withheld-effect benchmark (see :func:`.cli.main`)."""
import sys

from .cli import main

sys.exit(main())
