# SPDX-License-Identifier: GPL-3.0-or-later
"""Running .auto scripts in CPython, as AUTO's `auto X.auto` does: the
commands preloaded, the script's directory the working directory (where
its c./s./b./d. files are read and written), AUTO's shorthand `name args`
(Python-2 `print "..."`, `ld 'x'`) accepted.  An error stops the script with one line naming the
script's file and line, the line itself, and a non-zero exit status:

    cable: knot.auto:4: run: NMXX: unknown AUTO constant
        r = run(c='knot', NMXX=3)

Ctrl-C stops a run at its next point (nothing of that run is written) and
the script with status 130.
"""

__all__ = ['shorthand', 'py2_prints', 'compile_script', 'ScriptRunner',
           'Terminated', 'run_script', 'main']

import builtins
import io
import keyword
import os
import signal
import sys
import tokenize
import traceback
import types

from ._cable import CableError, blas_single_thread
from .commands import Runner, command_names

_STOPS = ('NEWLINE', 'ENDMARKER')


# what may follow NAME in AUTO's shorthand `NAME args` (its CLI's rule): not
# '(' ')' '=' '!' (a call, an assignment, a comparison), not an operator that
# makes `NAME op x` an expression, not is/not/in/and/or; '[' only for a
# callable without item access.  Python-2 print also takes a leading sign.
_NOT_ARGS_KW = ('is', 'not', 'in', 'and', 'or', 'if', 'else', 'for')
_ARG_OPS = ('[', '{', '~')


def _callable_in(namespace, name):
    if namespace is not None and name in namespace:
        obj = namespace.get(name)
    else:
        obj = getattr(builtins, name, None)
    return obj if callable(obj) else None


def shorthand(text, namespace=None):
    """AUTO's command-line shorthand rewritten as calls, as AUTO's CLI does
    for every line of a script: a statement `NAME args` whose NAME is a
    callable of the namespace (the commands) or a builtin becomes
    `NAME(args)`, a bare `NAME` becomes `NAME()`; so Python-2 `print "a", x`
    is print("a", x) (a trailing comma keeps the line open: end=' ') and
    `ld 'x'` is ld('x').  `NAME(...)`, `NAME = ...`, `NAME op ...`,
    `NAME.attr` and `x [1]` (indexing; x not a callable) keep their meaning.
    Only statement starts outside brackets are rewritten (never a continuation
    line or a string).  Text that does not tokenize is left as it is."""
    try:
        toks = list(tokenize.generate_tokens(io.StringIO(text).readline))
    except (tokenize.TokenError, IndentationError, SyntaxError):
        return text
    edits = []   # (row, col, insert) or (row, col, end_col, replacement)
    prev = None
    depth = 0
    for k, t in enumerate(toks):
        kind = tokenize.tok_name[t.type]
        if kind == 'OP' and t.string in '([{':
            depth += 1
        elif kind == 'OP' and t.string in ')]}':
            depth -= 1
        stmt_start = prev is None or prev in ('NEWLINE', 'INDENT', 'DEDENT',
                                              'NL') or prev == ':' or prev == ';'
        obj = (_callable_in(namespace, t.string)
               if kind == 'NAME' and depth == 0 and stmt_start and not keyword.iskeyword(t.string)
               else None)
        if obj is not None:
            nxt = toks[k + 1] if k + 1 < len(toks) else None
            nkind = tokenize.tok_name[nxt.type] if nxt else 'ENDMARKER'
            ends = nkind in _STOPS or nkind == 'COMMENT' or (nkind == 'OP' and nxt.string == ';')
            is_print = t.string == 'print'
            if ends or nkind in ('STRING', 'NUMBER'):
                args = True
            elif nkind == 'NAME':
                args = nxt.string not in _NOT_ARGS_KW
            elif nkind == 'OP':
                args = ((nxt.string in _ARG_OPS
                         and not (nxt.string == '[' and hasattr(obj, '__getitem__')))
                        or (is_print and nxt.string in ('-', '+')))
            else:
                args = False
            if args:
                # the end of the statement: NEWLINE, ';' or a comment at depth 0
                j, d = k + 1, 0
                while j < len(toks):
                    tk = tokenize.tok_name[toks[j].type]
                    if tk == 'OP' and toks[j].string in '([{':
                        d += 1
                    elif tk == 'OP' and toks[j].string in ')]}':
                        d -= 1
                    if d == 0 and (tk in _STOPS or tk == 'COMMENT'
                                   or (tk == 'OP' and toks[j].string == ';')):
                        break
                    j += 1
                last = toks[j - 1] if j - 1 > k else None
                if last is None:
                    edits.append((t.end[0], t.end[1], t.end[1], '()'))
                else:
                    gap = nxt.start[1] if nxt.start[0] == t.end[0] else t.end[1]
                    edits.append((t.end[0], t.end[1], gap, '('))
                    if is_print and tokenize.tok_name[last.type] == 'OP' and last.string == ',':
                        edits.append((last.start[0], last.start[1], last.end[1], ", end=' ')"))
                    else:
                        edits.append((last.end[0], last.end[1], ')'))
        if kind not in ('COMMENT', 'NL') or prev is None:
            prev = kind if kind != 'OP' else t.string
        if kind == 'NL' and depth == 0:
            prev = 'NL'
    if not edits:
        return text
    lines = text.splitlines(keepends=True)
    for e in sorted(edits, key=lambda e: (e[0], e[1]), reverse=True):
        row, col = e[0] - 1, e[1]
        line = lines[row]
        if len(e) == 3:
            lines[row] = line[:col] + e[2] + line[col:]
        else:
            lines[row] = line[:col] + e[3] + line[e[2]:]
    return ''.join(lines)


def py2_prints(text):
    """Python-2 print statements rewritten as calls (shorthand() with the builtins only)."""
    return shorthand(text, {})


def compile_script(text, filename, namespace=None):
    """The code object of a script, AUTO's shorthand rewritten first (as
    AUTO's CLI does) with the commands of the namespace.  The rewrite keeps
    every line where it was, so a syntax error names the script's line."""
    return compile(shorthand(text, namespace), filename, 'exec')


class ScriptRunner:
    """Runs scripts in one namespace on one runner (auto('other.auto') too)."""

    def __init__(self, runner=None):
        self.runner = runner or Runner()
        self.runner.script_runner = self.run_file
        self.namespace = self.runner.namespace()
        self.files = set()
        # a script that imports AUTO's modules by name (import AUTOclui,
        # from AUTOCommands import *) gets this runner's commands, as AUTO's
        # scripts get AUTO's runner's
        names = command_names()
        for mod in ('AUTOclui', 'AUTOCommands'):
            m = types.ModuleType(mod,
                                 "AUTO-07p's %s: cable's commands of the script's runner" % mod)
            m.__dict__.update({k: v for k, v in self.namespace.items() if k in names})
            m.__all__ = [k for k in names if k in self.namespace]
            sys.modules[mod] = m

    def run_file(self, path):
        with open(path, encoding='utf-8') as f:
            text = f.read()
        code = compile_script(text, path, self.namespace)
        self.files.add(path)
        ns = self.namespace
        ns['__name__'] = '__main__'
        ns['__file__'] = path
        exec(code, ns)

    def where(self, exc):
        """(file, line) of the innermost frame in one of the scripts."""
        if isinstance(exc, SyntaxError) and exc.filename in self.files | {exc.filename}:
            return exc.filename, exc.lineno or 0
        best = None
        for frame in traceback.extract_tb(exc.__traceback__):
            if frame.filename in self.files:
                best = (frame.filename, frame.lineno)
        return best


def _source_line(path, line):
    try:
        with open(path, encoding='utf-8') as f:
            for k, text in enumerate(f, 1):
                if k == line:
                    return text.rstrip('\n')
    except OSError:
        pass
    return None


def _report(path, line, msg, out, src_file=None):
    where = '%s:%d: ' % (path, line) if line else '%s: ' % path
    out.write('cable: %s%s\n' % (where, msg))
    src = _source_line(src_file or path, line) if line else None
    if src is not None and src.strip():
        out.write('    %s\n' % src.strip())


class Terminated(KeyboardInterrupt):
    """SIGTERM, raised like Ctrl-C's KeyboardInterrupt: a run stops after the
    point being computed and keeps its files."""


def _on_sigterm(signum, frame):
    raise Terminated('SIGTERM')


def run_script(path, out=None):
    """Run the script at path (outputs in its directory).  Returns the exit
    status: 0, 1 for an error (reported on out, default stderr), 130 when
    interrupted."""
    out = out or sys.stderr
    try:
        with open(path, encoding='utf-8') as f:
            f.read()
    except OSError as e:
        out.write('cable: %s: cannot open the script: %s\n' % (path, e.strerror or e))
        return 1
    sr = ScriptRunner()
    here = os.getcwd()
    d = os.path.dirname(path)
    name = os.path.abspath(path)
    sr.files.add(name)
    try:
        with open(path, encoding='utf-8') as f:
            text = f.read()
        code = compile_script(text, name, sr.namespace)
        if d:
            os.chdir(d)
        sr.namespace.update({'__name__': '__main__', '__file__': name})
        exec(code, sr.namespace)
        return 0
    except SyntaxError as e:
        fn = e.filename if e.filename in sr.files else name
        _report(_shown(fn, path, name), e.lineno or 0, '%s: %s' % (type(e).__name__, e.msg),
                out, fn)
        return 1
    except KeyboardInterrupt as e:
        sys.stdout.flush()
        w = sr.where(e) or (name, 0)
        notes = getattr(e, '__notes__', None)
        sig = 'SIGTERM' if isinstance(e, Terminated) else 'SIGINT'
        _report(_shown(w[0], path, name), w[1], 'stopped by %s: %s'
                % (sig, '; '.join(notes) if notes else
                'the script stopped; files written before are complete'), out, w[0])
        return 143 if isinstance(e, Terminated) else 130
    except CableError as e:
        sys.stdout.flush()
        w = sr.where(e) or (name, 0)
        _report(_shown(w[0], path, name), w[1], str(e), out, w[0])
        return 1
    except Exception as e:   # the script's own Python errors, as CPython names them
        sys.stdout.flush()
        w = sr.where(e) or (name, 0)
        _report(_shown(w[0], path, name), w[1], '%s: %s' % (type(e).__name__, e), out, w[0])
        return 1
    finally:
        os.chdir(here)


def _shown(fn, path, name):
    """The script's name as the user gave it; other scripts as compiled."""
    return path if fn == name else fn


def main(argv):
    if len(argv) != 1:
        sys.stderr.write('usage: python3 -m cable SCRIPT   (or: cable replay SCRIPT)\n')
        return 2
    # the application's setting, as the cable program makes it: the engine's
    # small blocks run fastest on one BLAS thread, and OpenBLAS's idle
    # threads spin (CABLE_BLAS_THREADS=n keeps n)
    blas_single_thread()
    # the application's too: SIGINT and SIGTERM end the script (exit 130,
    # 143) after the point being computed, keeping its files, and the log goes out line by line
    # into a file or a pipe
    signal.signal(signal.SIGTERM, _on_sigterm)
    signal.signal(signal.SIGINT,
                  signal.default_int_handler)   # also where the shell ignored it (cmd &)
    try:
        sys.stdout.reconfigure(line_buffering=True)
    except (AttributeError, ValueError):
        pass
    status = run_script(argv[0])
    sys.stdout.flush()
    return status
