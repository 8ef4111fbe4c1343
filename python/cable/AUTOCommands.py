# SPDX-License-Identifier: GPL-3.0-or-later
"""AUTO-07p's module AUTOCommands under its own name: scripts written for AUTO
that `import AUTOCommands` or `from AUTOCommands import *` get cable's commands (the
module runner's, cable.runner()), the same as AUTOclui's.  Inside `cable replay`
the top-level names AUTOclui and AUTOCommands are the script's own runner's
commands (cable.script).  What AUTO has and cable not: doc/scripts.md."""
from .AUTOclui import *  # noqa: F401,F403 (the same commands)
from .AUTOclui import __all__  # noqa: F401
