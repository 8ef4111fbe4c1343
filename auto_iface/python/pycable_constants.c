/* SPDX-License-Identifier: GPL-3.0-or-later */
/* AUTO constants (cable_constants) as a Python dict with AUTO's keys, in the
 * order of a constants file: what AUTO's pr() shows and s.c holds
 * (doc/scripts.md).  Values are written as a constants file would give them:
 * parameters by name where the names table names them (else AUTO's 1-based
 * index), IRS as its label name ('BP1') or number, STOP as ['BP1', ...].
 * A key that is not set is None (AUTO's parseC does the same): NDIM, NBC,
 * NINT until a constants file sets them (0: the problem's), BPANGLE when
 * BPDIR chooses the direction. */
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

PyObject *pyc_constants_dict(const cable_constants *c, const cable_names *n, const char *e)
{
  PyObject *d = PyDict_New();
  if (!d) return NULL;
  int rc = put_str(d, "e", e && e[0] ? e : c->e);
  if (!rc) rc = put_str(d, "s", c->s);
  if (!rc) rc = put_str(d, "dat", c->dat);
  if (!rc) rc = put_str(d, "sv", c->sv);
  if (!rc && n) {
    PyObject *u = names_dict(n->u), *p = names_dict(n->par);
    if (u && PyDict_Size(u) > 0) rc = put(d, "unames", u);
    else Py_XDECREF(u);
    if (p && PyDict_Size(p) > 0 && !rc) rc = put(d, "parnames", p);
    else Py_XDECREF(p);
    if (!u || !p) rc = -1;
  }
  if (!rc && c->npar_override > 0) rc = put(d, "PAR", par_dict(c, n));
  if (!rc) rc = put_dim(d, "NDIM", c->ndim, &c->origin_ndim);
  if (!rc) rc = put_int(d, "IPS", c->ips);
  if (!rc) rc = c->irs_name[0] ? put_str(d, "IRS", c->irs_name) : put_int(d, "IRS", c->irs);
  if (!rc) rc = put_int(d, "ILP", c->ilp);
  if (!rc) rc = put(d, "ICP", icp_list(c, n));
  const struct {
    const char *key;
    int v;
  } ints[] = {{"NTST", c->ntst}, {"NCOL", c->ncol}, {"IAD", c->iad},   {"ISP", c->isp},   {"ISW", c->isw},
              {"IPLT", c->iplt}, {"NMX", c->nmx},   {"NPR", c->npr},   {"IID", c->iid},   {"ITMX", c->itmx},
              {"ITNW", c->itnw}, {"NWTN", c->nwtn}, {"JAC", c->jac}};
  for (size_t k = 0; !rc && k < sizeof ints / sizeof ints[0]; k++) {
    rc = put_int(d, ints[k].key, ints[k].v);
    if (!rc && strcmp(ints[k].key, "IPLT") == 0) rc = put_dim(d, "NBC", c->nbc, &c->origin_nbc);
    if (!rc && strcmp(ints[k].key, "IPLT") == 0) rc = put_dim(d, "NINT", c->nint, &c->origin_nint);
  }
  const struct {
    const char *key;
    double v;
  } reals[] = {{"EPSL", c->epsl}, {"EPSU", c->epsu}, {"EPSS", c->epss}, {"DS", c->ds}, {"DSMIN", c->dsmin},
               {"DSMAX", c->dsmax}};
  for (size_t k = 0; !rc && k < sizeof reals / sizeof reals[0]; k++) rc = put_real(d, reals[k].key, reals[k].v);
  if (!rc) rc = put_int(d, "IADS", c->iads);
  if (!rc) rc = put_int(d, "NPAR", c->npar);
  if (!rc) rc = put(d, "THL", thl_dict(c, n));
  if (!rc) rc = put(d, "THU", thu_dict(c));
  if (!rc) rc = put_int(d, "IIS", c->iis);
  if (!rc) rc = put(d, "UZR", uzr_dict(c, n, 0));
  if (!rc) rc = put(d, "UZSTOP", uzr_dict(c, n, 1));
  if (!rc) rc = put(d, "STOP", stop_list(c));
  if (!rc) rc = put_real(d, "RL0", c->rl0);
  if (!rc) rc = put_real(d, "RL1", c->rl1);
  if (!rc) rc = put_real(d, "A0", c->a0);
  if (!rc) rc = put_real(d, "A1", c->a1);
  /* cable's own keys (doc/constants.md) and the problem's keys as set */
  if (!rc) rc = put_str(d, "LINSOLVER", c->linsolver == CABLE_LINSOLVER_KLU ? "klu" : "condense");
  if (!rc) rc = put_int(d, "NSV", c->nsv);
  if (!rc) rc = put_int(d, "NTHREADS", c->nthreads);
  if (!rc) rc = put_int(d, "BPDIR", c->bpsym);
  if (!rc) rc = put_int(d, "PREDICTOR", c->predictor);
  if (!rc && isnan(c->bpangle)) {
    Py_INCREF(Py_None);
    rc = put(d, "BPANGLE", Py_None);
  } else if (!rc) {
    rc = put_real(d, "BPANGLE", c->bpangle);
  }
  for (int k = 0; !rc && k < c->npkey && k < CABLE_MAX_PKEYS; k++) rc = put(d, c->pkey[k].name, key_value(c->pkey[k].value));
  if (rc) Py_CLEAR(d);
  return d;
}
