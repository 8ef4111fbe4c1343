# SPDX-License-Identifier: GPL-3.0-or-later
"""AUTO constants as a Python object (AUTO's parseC): what pr() shows and
s.c holds.  A Constants is a dict with AUTO's keys (doc/constants.md) whose
str() is a constants file in AUTO's layout (the keys grouped on lines as a
c-file has them), readable again by ld(c=...) and `cable run`.  A missing
key is a cable.CableError naming it; a key that is not set is None (AUTO's
way) and is not printed.
"""

__all__ = ['layout', 'Constants']

from ._cable import CableError, constants_layout
from .errors import CableKeyError

# the keys of one line of the printed file, in a constants file's order: the
# line column of the C key table (include/cable/cable_constants_keys.h); the
# problem's own keys (TORUS, HAND ...) follow on a line of their own
_LINES = constants_layout()
_KNOWN = frozenset(k for line in _LINES for k in line)


def _text(v):
    """A value in the constants-file syntax (Python's literals; numbers as repr)."""
    if isinstance(v, dict):
        return '{' + ', '.join('%s: %s' % (_text(k), _text(x)) for k, x in v.items()) + '}'
    if isinstance(v, list):
        return '[' + ', '.join(_text(x) for x in v) + ']'
    if isinstance(v, str):
        return '"%s"' % v if "'" in v else "'%s'" % v
    return repr(v)


def layout(constants):
    """The constants as a constants file in AUTO's layout (one string)."""
    lines = []
    rest = tuple(k for k in constants if k not in _KNOWN)
    for keys in _LINES + ((rest,) if rest else ()):
        items = ['%s = %s' % (k, _text(constants[k])) for k in keys
                 if constants.get(k) is not None]
        if items:
            lines.append(', '.join(items))
    return '\n'.join(lines) + '\n'


class Constants(dict):
    """AUTO's constants: c['NTST'], c['ICP'], c['UZR'] ... (numbers, lists,
    dicts, names as a constants file gives them); print(c) shows the file."""

    def __missing__(self, key):
        raise CableKeyError('%s: unknown key' % (key,))

    def __str__(self):
        return layout(self)
