# SPDX-License-Identifier: GPL-3.0-or-later
"""cable's exceptions are also the built-ins Python code catches (issue 27):
CableError stays the base, and an error of a known kind is as well a
TypeError, KeyError, ValueError or FileNotFoundError, its message (the
command's name, then cable's own words) intact."""
import pytest

import cable
from cable import errors
from conftest import run_script


def _caught(builtin, fn):
    with pytest.raises(builtin) as info:
        fn()
    e = info.value
    assert isinstance(e, cable.CableError)
    return e


def test_key_error(work):
    e = _caught(KeyError, lambda: cable.Constants()['NOPE'])
    assert isinstance(e, cable.CableKeyError)
    # KeyError's str() would be the repr; cable's message reads as written
    assert str(e) == 'NOPE: unknown key'


def test_type_error(work):
    e = _caught(TypeError, lambda: cable.loadbd(5))
    assert str(e) == 'loadbd: loadbd needs a name (files b.NAME, s.NAME)'
    assert e.command == 'loadbd' and e.status == -2


def test_value_error(work):
    e = _caught(ValueError, lambda: cable.run([[0, 1, 0.5], [1, 2, 3]], e='braid_knot'))
    assert str(e) == 'run: start data: t (the first column) must increase'


def test_file_not_found_error(work):
    e = _caught(FileNotFoundError, lambda: cable.copy('nonexist', 'b'))
    assert isinstance(e, OSError)
    assert str(e) == 'copy: nonexist: no files b./s./d.nonexist'


def test_except_cable_error_still_catches_all(work):
    for fn in (lambda: cable.Constants()['NOPE'], lambda: cable.loadbd(5)):
        with pytest.raises(cable.CableError):
            fn()
    assert set(errors.__all__) == {'CableError', 'CableTypeError', 'CableKeyError',
                                   'CableValueError', 'CableFileNotFoundError'}


def test_script_report_unchanged(work):
    """A script's error is reported as before: file, line, cable's message,
    no Python class name in front."""
    rc, out, err = run_script(work, "x = 1\nloadbd(5)\n")
    assert rc == 1
    assert 't.auto:2: loadbd: loadbd needs a name (files b.NAME, s.NAME)' in out + err, out + err
    assert 'CableTypeError' not in out + err and 'TypeError' not in out + err


# Errors the library reports (the C extension raises them): the class follows
# the status, so a bad constant is a ValueError, an unknown problem a KeyError
# and a missing file a FileNotFoundError, each with cable's file:line:key words.
def test_library_value_error(work):
    with open('c.bad', 'w') as f:
        f.write("e = 'bratu'\nICP = ['lambda']\nNTST = -5\n")
    e = _caught(ValueError, lambda: cable.run(c='bad', NMX=3))
    assert isinstance(e, cable.CableValueError)
    assert 'c.bad:3' in str(e) and 'NTST' in str(e), str(e)
    e = _caught(ValueError, lambda: cable.run(e='bratu', ICP=['lambda'], NMX=3, BRANCH=99))
    assert 'BRANCH' in str(e) and '0..8' in str(e), str(e)


def test_library_key_error(work):
    e = _caught(KeyError, lambda: cable.run(e='nosuchproblem', NMX=3))
    assert isinstance(e, cable.CableKeyError)
    assert str(e).startswith("run: e: unknown problem 'nosuchproblem'"), str(e)


def test_library_file_not_found_error(work):
    e = _caught(FileNotFoundError, lambda: cable.run(e='bratu', c='nosuchfile', NMX=3))
    assert str(e) == 'run: c.nosuchfile: cannot open constants file: No such file or directory'
    e = _caught(FileNotFoundError, lambda: cable.loadbd('nosuch'))
    assert 's.nosuch' in str(e)


def test_library_io_error_of_an_existing_file_is_not_file_not_found(work):
    """A file that exists but cannot be read as a constants file is not a
    FileNotFoundError (the error names a file that is there)."""
    with open('c.dir', 'w') as f:
        f.write("e = 'bratu'\nICP = ['lambda'\n")
    with pytest.raises(cable.CableError) as info:
        cable.run(c='dir', NMX=3)
    assert not isinstance(info.value, FileNotFoundError)
    assert 'c.dir' in str(info.value)
