# SPDX-License-Identifier: GPL-3.0-or-later
"""Files written whole or not at all, the Python side of cable's one atomic
writer (continuation/atomic_file.c): the text goes to a temporary file in
the destination's directory, renamed over the destination only when it is
complete, so a reader never sees half a file and a failure leaves the old
one untouched.  New files get mode 0644, as the C writer gives them."""

__all__ = ['replacing', 'write_text', 'copy_file']

import contextlib
import os
import tempfile

NEW_FILE_MODE = 0o644


@contextlib.contextmanager
def replacing(path, suffix='', mode=NEW_FILE_MODE):
    """with replacing(path) as tmp: write tmp; it is renamed over path when
    the block ends normally and removed when it raises.  suffix: the
    temporary name's ending (a writer that picks the format by it); mode:
    the file's permissions."""
    d = os.path.dirname(os.path.abspath(path))
    fd, tmp = tempfile.mkstemp(prefix='.%s.' % os.path.basename(path),
                               suffix=suffix, dir=d)
    os.close(fd)
    try:
        yield tmp
        os.chmod(tmp, mode)
        os.replace(tmp, path)
    finally:
        if os.path.exists(tmp):
            os.remove(tmp)


def write_text(path, text, encoding='utf-8', mode=NEW_FILE_MODE):
    """Write text to path whole or not at all (newlines as given)."""
    with replacing(path, mode=mode) as tmp:
        with open(tmp, 'w', encoding=encoding, newline='') as f:
            f.write(text)
    return path


def copy_file(src, dst):
    """Copy src's bytes to dst whole or not at all."""
    import shutil
    with replacing(dst) as tmp:
        shutil.copyfile(src, tmp)
    return dst
