/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Internals of the extension module cable._cable (auto_iface/python/pycable_*.c).
 * It uses libcable's public API only (include/cable/). */
#ifndef CABLE_PYCABLE_H
#define CABLE_PYCABLE_H

#define PY_SSIZE_T_CLEAN
#include <Python.h>

#include "cable/cable.h"
#include "cable/cable_session.h"

/* A Branch object: one reference of a session branch. */
typedef struct pyc_branch {
  PyObject_HEAD
  cable_branch *b;
} pyc_branch;

extern PyTypeObject pyc_branch_type;
extern PyTypeObject pyc_session_type;

/* Raises cable.CableError with the library's message (file:line: key: msg)
 * and .status; keeps a pending KeyboardInterrupt for an interrupted run.
 * Returns NULL. */
PyObject *pyc_raise(int status, const cable_error *err);
/* A Branch owning b (the reference is taken over; NULL with an exception). */
PyObject *pyc_branch_wrap(cable_branch *b);
/* A list of Branch objects from list[0..n-1] (taken over and freed). */
PyObject *pyc_branch_list(cable_branch **list, int n);
/* Borrowed branch pointers of a sequence of Branch objects (PyMem_Free *out). */
int pyc_branches_from(PyObject *seq, cable_branch ***out, int *n);
/* The solution i of a Branch argument, or NULL with an exception. */
const cable_solution *pyc_solution_arg(PyObject *branch, int i);

/* AUTO constants as a dict with AUTO's keys (pycable_constants.c); names
 * name the parameters (NULL: indices); e the problem (NULL: c->e). */
PyObject *pyc_constants_dict(const cable_constants *c, const cable_names *names, const char *e);
/* _cable.constants_layout(): the keys of each printed line, from the key table */
PyObject *pyc_constants_layout(PyObject *self, PyObject *unused);

PyObject *pyc_analyze(PyObject *mod, PyObject *args);
PyObject *pyc_passages(PyObject *mod, PyObject *args);
PyObject *pyc_tube_dmin(PyObject *mod, PyObject *args);
PyObject *pyc_curves(PyObject *mod, PyObject *args);
PyObject *pyc_plot(PyObject *mod, PyObject *args);
PyObject *pyc_render(PyObject *mod, PyObject *args);
PyObject *pyc_strands(PyObject *mod, PyObject *args);
PyObject *pyc_bfile(PyObject *mod, PyObject *args);

#endif
