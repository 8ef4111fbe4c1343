# SPDX-License-Identifier: GPL-3.0-or-later
"""python3 -m cable SCRIPT: run a script with AUTO's commands preloaded (cable.script)."""
import sys

from .script import main

sys.exit(main(sys.argv[1:]))
