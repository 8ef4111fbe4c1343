# SPDX-License-Identifier: GPL-3.0-or-later
"""cable's exceptions.  CableError (a RuntimeError) is the base of all: its
message names what is wrong (file, line and key where there is one) and
`except CableError` catches every error cable raises.  Where an error is
one of the kinds Python code expects, it is also that built-in, so that
`except TypeError` (a wrong kind of argument), `except KeyError` (no such
key, parameter, label or column), `except ValueError` (a bad value) or
`except FileNotFoundError` (no such file or directory) catch it with
cable's message intact."""

__all__ = ['CableError', 'CableTypeError', 'CableKeyError', 'CableValueError',
           'CableFileNotFoundError']

from ._cable import CableError


class CableTypeError(CableError, TypeError):
    """A wrong kind of argument."""


class CableKeyError(CableError, KeyError):
    """No such constants key, parameter, component, label or column."""

    # KeyError's str() is the repr of the key; cable's message reads as written
    __str__ = CableError.__str__


class CableValueError(CableError, ValueError):
    """An argument of the right kind with a wrong value."""


class CableFileNotFoundError(CableError, FileNotFoundError):
    """No such file or directory (the message names it)."""
