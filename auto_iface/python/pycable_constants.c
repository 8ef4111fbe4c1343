/* SPDX-License-Identifier: GPL-3.0-or-later */
/* AUTO constants (cable_constants) as a Python dict with AUTO's keys, in the
 * order of a constants file: what AUTO's pr() shows and s.c holds
 * (doc/scripts.md).  Values are written as a constants file would give them:
 * parameters by name where the names table names them (else AUTO's 1-based
 * index), IRS as its label name ('BP1') or number, STOP as ['BP1', ...].
 * A key that is not set is None (AUTO's parseC does the same): NDIM, NBC,
 * NINT until a constants file sets them (0: the problem's), BPANGLE when
 * BPDIR chooses the direction.  The keys, their order and their kinds are
 * the rows of cable/cable_constants_keys.h. */
#include <math.h>
#include <string.h>

#include "pycable.h"

/* A new reference to the name of 0-based parameter k, or its 1-based index. */
static PyObject *par_key(const cable_names *n, int k)
{
  if (n && k >= 0 && k < CABLE_NAMES_MAX && n->par[k][0]) return PyUnicode_FromString(n->par[k]);
  return PyLong_FromLong(k + 1);
}

/* Sets d[key] = v and drops the reference to v; -1 with an exception. */
static int put(PyObject *d, const char *key, PyObject *v)
{
  if (!v) return -1;
  int rc = PyDict_SetItemString(d, key, v);
  Py_DECREF(v);
  return rc;
}

static int put_int(PyObject *d, const char *key, long v)
{
  return put(d, key, PyLong_FromLong(v));
}

static int put_real(PyObject *d, const char *key, double v)
{
  return put(d, key, PyFloat_FromDouble(v));
}

static int put_str(PyObject *d, const char *key, const char *v)
{
  if (!v || !v[0]) return 0;   /* unset names are not shown */
  return put(d, key, PyUnicode_FromString(v));
}

/* NDIM, NBC, NINT: 0 and not set means "the problem's", shown as unset. */
static int put_dim(PyObject *d, const char *key, int v, const cable_key_origin *o)
{
  if (v > 0 || o->file[0] || o->line) return put_int(d, key, v);
  Py_INCREF(Py_None);
  return put(d, key, Py_None);
}

/* {index: 'name'} of the named slots of a names table. */
static PyObject *names_dict(const char (*names)[CABLE_NAME_LEN])
{
  PyObject *d = PyDict_New();
  for (int k = 0; d && k < CABLE_NAMES_MAX; k++) {
    if (!names[k][0]) continue;
    PyObject *key = PyLong_FromLong(k + 1), *v = PyUnicode_FromString(names[k]);
    int rc = key && v ? PyDict_SetItem(d, key, v) : -1;
    Py_XDECREF(key);
    Py_XDECREF(v);
    if (rc < 0) Py_CLEAR(d);
  }
  return d;
}

/* d[key] = value, with a new reference to key dropped. */
static int set_item(PyObject *d, PyObject *key, PyObject *value)
{
  int rc = key && value ? PyDict_SetItem(d, key, value) : -1;
  Py_XDECREF(key);
  Py_XDECREF(value);
  return rc;
}

/* UZR (stop 0) or UZSTOP (stop 1): {par: value} for one value, {par: [values]} for several. */
static PyObject *uzr_dict(const cable_constants *c, const cable_names *n, int stop)
{
  PyObject *d = PyDict_New();
  for (int k = 0; d && k < c->nuzr; k++) {
    if (!c->uzr[k].stop != !stop) continue;
    PyObject *key = par_key(n, c->uzr[k].par), *v = PyFloat_FromDouble(c->uzr[k].value);
    int rc = -1;
    if (key && v) {
      PyObject *old = PyDict_GetItemWithError(d, key);   /* borrowed */
      if (!old && !PyErr_Occurred()) {
        rc = PyDict_SetItem(d, key, v);
      } else if (old && PyList_Check(old)) {
        rc = PyList_Append(old, v);
      } else if (old) {   /* a second value: the entry becomes a list */
        PyObject *l = PyList_New(2);
        if (l) {
          Py_INCREF(old);
          Py_INCREF(v);
          PyList_SET_ITEM(l, 0, old);
          PyList_SET_ITEM(l, 1, v);
          rc = PyDict_SetItem(d, key, l);
          Py_DECREF(l);
        }
      }
    }
    Py_XDECREF(key);
    Py_XDECREF(v);
    if (rc < 0) Py_CLEAR(d);
  }
  return d;
}

static PyObject *icp_list(const cable_constants *c, const cable_names *n)
{
  PyObject *l = PyList_New(c->nicp);
  for (int k = 0; l && k < c->nicp; k++) {
    PyObject *v = par_key(n, c->icp[k]);
    if (!v) Py_CLEAR(l);
    else PyList_SET_ITEM(l, k, v);
  }
  return l;
}

static PyObject *thl_dict(const cable_constants *c, const cable_names *n)
{
  PyObject *d = PyDict_New();
  for (int k = 0; d && k < c->nthl; k++)
    if (set_item(d, par_key(n, c->thl[k].index), PyFloat_FromDouble(c->thl[k].weight)) < 0) Py_CLEAR(d);
  return d;
}

/* THU: cable keeps one weight for every component (doc/constants.md): {}
 * for 1, else that weight for U(1)..U(NDIM). */
static PyObject *thu_dict(const cable_constants *c)
{
  PyObject *d = PyDict_New();
  if (!d || c->thu_default == 1.0) return d;
  for (int k = 0; k < c->ndim; k++)
    if (set_item(d, PyLong_FromLong(k + 1), PyFloat_FromDouble(c->thu_default)) < 0) {
      Py_CLEAR(d);
      break;
    }
  return d;
}

static PyObject *par_dict(const cable_constants *c, const cable_names *n)
{
  PyObject *d = PyDict_New();
  for (int k = 0; d && k < c->npar_override; k++)
    if (set_item(d, par_key(n, c->par_override[k].index), PyFloat_FromDouble(c->par_override[k].value)) < 0)
      Py_CLEAR(d);
  return d;
}

static PyObject *stop_list(const cable_constants *c)
{
  PyObject *l = PyList_New(c->nstop);
  for (int k = 0; l && k < c->nstop; k++) {
    PyObject *v = PyUnicode_FromFormat("%s%d", cable_type_name(c->stop_on[k]), c->stop_count[k]);
    if (!v) Py_CLEAR(l);
    else PyList_SET_ITEM(l, k, v);
  }
  return l;
}

/* A problem key's value: an int when it is one (TORUS=3), else a float. */
static PyObject *key_value(double v)
{
  if (v == floor(v) && fabs(v) < 1e15) return PyLong_FromDouble(v);
  return PyFloat_FromDouble(v);
}

/* unames (n->u) or parnames (n->par): shown when one is named */
static int put_names(PyObject *d, const char *key, const cable_names *n)
{
  if (!n) return 0;
  PyObject *v = names_dict(strcmp(key, "unames") == 0 ? n->u : n->par);
  if (v && PyDict_Size(v) > 0) return put(d, key, v);
  Py_XDECREF(v);
  return v ? 0 : -1;
}

/* A real that is NaN is not set (BPANGLE when BPDIR chooses): None. */
static int put_real_or_none(PyObject *d, const char *key, double v)
{
  if (!isnan(v)) return put_real(d, key, v);
  Py_INCREF(Py_None);
  return put(d, key, Py_None);
}

/* Each kind of cable/cable_constants_keys.h as a Python value: a new entry
 * d[key], 0 or -1 with an exception. */
#define PY_INT(key, f) put_int(d, key, c->f)
#define PY_NPAR PY_INT
#define PY_IPS PY_INT
#define PY_ISW PY_INT
#define PY_STAB PY_INT
#define PY_DIM(key, f) put_dim(d, key, c->f, &c->origin_##f)
#define PY_REAL(key, f) put_real_or_none(d, key, c->f)
#define PY_POS(key, f) put_real(d, key, c->f)
#define PY_DS PY_POS
#define PY_STR(key, f) put_str(d, key, c->f)
#define PY_NAME(key, f) put_str(d, key, e && e[0] ? e : c->f)
#define PY_NAMES(key, f) put_names(d, key, n)
#define PY_PAR(key, f) (c->n##f > 0 ? put(d, key, par_dict(c, n)) : 0)
#define PY_IRS(key, f) (c->f##_name[0] ? put_str(d, key, c->f##_name) : put_int(d, key, c->f))
#define PY_ICP(key, f) put(d, key, icp_list(c, n))
#define PY_THL(key, f) put(d, key, thl_dict(c, n))
#define PY_THU(key, f) put(d, key, thu_dict(c))
#define PY_UZR(key, f) put(d, key, uzr_dict(c, n, 0))
#define PY_UZSTOP(key, f) put(d, key, uzr_dict(c, n, 1))
#define PY_STOP(key, f) put(d, key, stop_list(c))
#define PY_LINSOLVER(key, f) put_str(d, key, c->f == CABLE_LINSOLVER_KLU ? "klu" : "condense")

PyObject *pyc_constants_dict(const cable_constants *c, const cable_names *n, const char *e)
{
  PyObject *d = PyDict_New();
  if (!d) return NULL;
  int rc = 0;
  /* the keys in the table's order; those on no printed line (0) are not shown */
#define PY_ROW(key, field, kind, who, def, lo, hi, line) \
  if (!rc && (line) > 0) rc = PY_##kind(#key, field);
  CABLE_CONSTANTS_KEYS(PY_ROW)
#undef PY_ROW
  /* the problem's keys as set */
  for (int k = 0; !rc && k < c->npkey && k < CABLE_MAX_PKEYS; k++) rc = put(d, c->pkey[k].name, key_value(c->pkey[k].value));
  if (rc) Py_CLEAR(d);
  return d;
}

/* The printed layout (python/cable/constants.py): a tuple of lines, each a
 * tuple of the keys on it, from the table's line column. */
PyObject *pyc_constants_layout(PyObject *self, PyObject *unused)
{
  (void)self;
  (void)unused;
  static const struct {
    const char *key;
    int line;
  } rows[] = {
#define LAYOUT_ROW(key, field, kind, who, def, lo, hi, line) {#key, line},
      CABLE_CONSTANTS_KEYS(LAYOUT_ROW)
#undef LAYOUT_ROW
  };
  enum { NROWS = (int)(sizeof rows / sizeof rows[0]) };
  int nlines = 0;
  for (int k = 0; k < NROWS; k++)
    if (rows[k].line > nlines) nlines = rows[k].line;
  PyObject *out = PyTuple_New(nlines);
  for (int l = 1; out && l <= nlines; l++) {
    PyObject *keys = PyList_New(0);
    for (int k = 0; keys && k < NROWS; k++) {
      if (rows[k].line != l) continue;
      PyObject *v = PyUnicode_FromString(rows[k].key);
      if (!v || PyList_Append(keys, v) < 0) Py_CLEAR(keys);
      Py_XDECREF(v);
    }
    PyObject *t = keys ? PyList_AsTuple(keys) : NULL;
    Py_XDECREF(keys);
    if (!t) Py_CLEAR(out);
    else PyTuple_SET_ITEM(out, l - 1, t);
  }
  return out;
}
