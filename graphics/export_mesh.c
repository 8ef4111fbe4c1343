/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Input checks and meshes for the exporters. */
#include "export_mesh.h"

#include <ctype.h>
#include <math.h>
#include <stddef.h>
#include <stdlib.h>

#include "cable/cable_status.h"

static int export_name_ok(const char *s)
{
  if (s == NULL) return 1;
  if (s[0] == '\0') return 0;
  for (; *s; s++)
    if (!isalnum((unsigned char)*s) && *s != '_' && *s != '-') return 0;
  return 1;
}

int export_check(const render_tube *tubes, int ntube, const render_profile *curves, int ncurve,
                 const export_options *opt, const char *path, int *nsides)
{
  if (tubes == NULL || ntube < 1 || path == NULL || path[0] == '\0') return CABLE_ERR_INPUT;
  if (ncurve < 0 || (ncurve > 0 && curves == NULL)) return CABLE_ERR_INPUT;
  *nsides = opt && opt->nsides != 0 ? opt->nsides : EXPORT_NSIDES_DEFAULT;
  if (*nsides < TUBE_NSIDES_MIN || *nsides > TUBE_NSIDES_MAX) return CABLE_ERR_INPUT;
  if (opt && !export_name_ok(opt->scalar_name)) return CABLE_ERR_INPUT;
  for (int k = 0; k < ntube; k++) {
    const render_tube *t = tubes + k;
    if (t->n < 2 || t->xyz == NULL || !(t->radius > 0) || !isfinite(t->radius)) return CABLE_ERR_INPUT;
    for (int i = 0; i < t->n; i++)
      if (!isfinite(t->xyz[3 * i]) || !isfinite(t->xyz[3 * i + 1]) || !isfinite(t->xyz[3 * i + 2]) ||
          (t->scalar && !isfinite(t->scalar[i])))
        return CABLE_ERR_INPUT;
  }
  for (int k = 0; k < ncurve; k++) {
    const render_profile *c = curves + k;
    if (c->n < 2 || c->xyz == NULL || c->value == NULL) return CABLE_ERR_INPUT;
    for (int i = 0; i < c->n; i++)
      if (!isfinite(c->xyz[3 * i]) || !isfinite(c->xyz[3 * i + 1]) || !isfinite(c->xyz[3 * i + 2]) ||
          !isfinite(c->value[i]))
        return CABLE_ERR_INPUT;
  }
  return CABLE_SUCCESS;
}

void export_meshes_free(tube_mesh **m, int ntube)
{
  for (int k = 0; k < ntube; k++) {
    tube_mesh_free(m[k]);
    m[k] = NULL;
  }
}

int export_meshes_build(const render_tube *tubes, int ntube, int nsides, tube_mesh **m)
{
  for (int k = 0; k < ntube; k++) m[k] = NULL;
  for (int k = 0; k < ntube; k++) {
    const render_tube *t = tubes + k;
    m[k] = tube_mesh_alloc(tube_points_count(t->n, t->xyz, t->closed), nsides, t->closed);
    int st = m[k] ? tube_mesh_build(m[k], t->xyz, t->scalar, t->radius) : CABLE_ERR_ALLOC;
    if (st != CABLE_SUCCESS) {
      export_meshes_free(m, k + 1);
      return st;
    }
  }
  return CABLE_SUCCESS;
}

int export_begin(const render_tube *tubes, int ntube, const render_profile *curves, int ncurve,
                 const export_options *opt, const char *path, export_out *out)
{
  int nsides;
  int st = export_check(tubes, ntube, curves, ncurve, opt, path, &nsides);
  if (st != CABLE_SUCCESS) return st;
  tube_mesh **m = malloc(sizeof *m * (size_t)ntube);
  if (m == NULL) return CABLE_ERR_ALLOC;
  if ((st = export_meshes_build(tubes, ntube, nsides, m)) != CABLE_SUCCESS) {
    free(m);
    return st;
  }
  cable_atomic_file *gf = cable_atomic_open(path, 0, NULL);
  if (gf == NULL) {
    export_meshes_free(m, ntube);
    free(m);
    return CABLE_ERR_IO;
  }
  *out = (export_out){m, ntube, gf, cable_atomic_stream(gf)};
  return CABLE_SUCCESS;
}

int export_end(export_out *out)
{
  export_meshes_free(out->m, out->ntube);
  free(out->m);
  out->m = NULL;
  return cable_atomic_commit(out->file, NULL);
}
