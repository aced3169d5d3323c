"""``python -m frictionlab``: the ``frictionlab`` command where its script is not on PATH
(a venv used without activating it)."""
import sys

from frictionlab.cli import main

sys.exit(main())
