# SPDX-License-Identifier: GPL-3.0-or-later
"""AUTO-07p's module AUTOclui under its own name: scripts written for AUTO
that `import AUTOclui` or `from AUTOclui import *` get cable's commands (the
module runner's, cable.runner()).  Inside `cable replay` the top-level
names AUTOclui and AUTOCommands are the script's own runner's commands
(cable.script).  What AUTO has and cable not: doc/scripts.md."""
from . import _delegate as _delegate_fn
from .commands import command_names as _names

__all__ = _names()
for _n in __all__:
    globals()[_n] = _delegate_fn(_n)
del _n
