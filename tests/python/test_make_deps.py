# SPDX-License-Identifier: GPL-3.0-or-later
"""Plain `make` builds only (issue 27): it checks the build dependencies and
names a missing one with the command that installs it, never running apt;
the README's commands (make check, make demo) and `make deps` install."""
import os
import re
import subprocess

from conftest import ROOT

SCRIPT = os.path.join(ROOT, 'scripts', 'install-deps.sh')

# The build's probes (scripts/install-deps.sh, build_probes) as files under a
# fake root: what `make` needs, and nothing of the tests' tools.
BUILD_FILES = [
    'usr/include/kinsol/kinsol.h', 'usr/include/sunlinsol/sunlinsol_klu.h',
    'usr/include/suitesparse/klu.h', 'usr/include/lapacke.h',
    'usr/lib/ARCH/liblapack.so', 'usr/lib/ARCH/libopenblas.so',
    'usr/lib/ARCH/openblas-pthread/libopenblas.a', 'usr/lib/ARCH/liblapacke.a',
    'usr/include/gsl/gsl_version.h', 'usr/include/cairo/cairo.h',
    'usr/bin/gfortran', 'usr/bin/python3', 'usr/include/python3.11/Python.h',
    'usr/lib/python3/dist-packages/numpy/core/include/numpy/arrayobject.h']


def _arch():
    try:
        p = subprocess.run(['dpkg-architecture', '-qDEB_HOST_MULTIARCH'],
                           capture_output=True, text=True)
        if p.returncode == 0 and p.stdout.strip():
            return p.stdout.strip()
    except OSError:
        pass
    return 'x86_64-linux-gnu'


def _run(root, tmp_path, *args):
    """The script with its probes under root and an apt-get/sudo on PATH that
    only leave a mark; returns (status, stderr, apt was called)."""
    bin_dir = tmp_path / 'fakebin'
    bin_dir.mkdir(exist_ok=True)
    mark = tmp_path / 'apt-called'
    for name in ('apt-get', 'sudo'):
        f = bin_dir / name
        f.write_text('#!/bin/sh\ntouch %s\n' % mark)
        f.chmod(0o755)
    env = dict(os.environ, CABLE_DEPS_ROOT=str(root),
               PATH='%s:%s' % (bin_dir, os.environ.get('PATH', '')))
    p = subprocess.run(['bash', SCRIPT] + list(args), capture_output=True,
                       text=True, env=env)
    return p.returncode, p.stderr, mark.exists()


def test_check_build_names_the_package_and_the_command(tmp_path):
    root = tmp_path / 'root'
    arch = _arch()
    for f in BUILD_FILES:
        if f.endswith('gsl_version.h'):
            continue   # libgsl-dev is missing
        p = root / f.replace('ARCH', arch)
        p.parent.mkdir(parents=True, exist_ok=True)
        p.write_text('')
    rc, err, apt = _run(root, tmp_path, '--check-build')
    assert rc == 1 and not apt, err
    assert 'missing build dependencies (Debian packages): libgsl-dev\n' in err
    assert 'sudo apt-get install libgsl-dev' in err


def test_check_build_needs_no_test_tools(tmp_path):
    """All build files present, none of the tests' (auto-07p, pytest,
    chromium, ...): plain make's check passes and installs nothing."""
    root = tmp_path / 'root'
    arch = _arch()
    for f in BUILD_FILES:
        p = root / f.replace('ARCH', arch)
        p.parent.mkdir(parents=True, exist_ok=True)
        p.write_text('')
    rc, err, apt = _run(root, tmp_path, '--check-build')
    assert rc == 0 and err == '' and not apt
    # the full check does see the tests' tools missing
    rc, err, apt = _run(root, tmp_path, '--check')
    assert rc == 1 and 'auto-07p' in err and 'python3-pytest' in err
    assert not apt


def _dry_run(goal):
    p = subprocess.run(['make', '-n', '-B', '--no-print-directory', goal],
                       cwd=ROOT, capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    return [ln.strip() for ln in p.stdout.splitlines()
            if 'install-deps.sh' in ln]


def test_plain_make_only_checks_and_make_check_installs():
    assert _dry_run('all') == ['bash scripts/install-deps.sh --check-build']
    assert _dry_run('check') == ['bash scripts/install-deps.sh']
    assert _dry_run('deps') == ['bash scripts/install-deps.sh']


def test_readme_commands_install():
    """The README's two commands are make demo and make check, both in the
    Makefile's installing goals."""
    with open(os.path.join(ROOT, 'README.md')) as f:
        readme = f.read()
    block = readme.split('## The two commands', 1)[1].split('##', 1)[0]
    goals = re.findall(r'^ {4}make (\w+)', block, re.M)
    assert goals == ['demo', 'check']
    with open(os.path.join(ROOT, 'Makefile')) as f:
        mk = f.read()
    installing = re.search(r'^INSTALL_GOALS := (.*)$', mk, re.M).group(1)
    assert set(goals) <= set(installing.split())
