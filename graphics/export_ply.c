/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Stanford PLY (ASCII) writer. */
#include <math.h>
#include <stdio.h>

#include "cable/cable_status.h"
#include "export_mesh.h"

/* PLY floats are single precision: 9 significant digits round-trip them. */
#define EXPORT_PLY_FMT "%.9g"

static int ply_byte(double v)
{
  v = v < 0 ? 0 : v > 1 ? 1 : v;
  return (int)lround(255.0 * v);
}

int export_ply_write(const render_tube *tubes, int ntube, const export_options *opt,
                     const char *path)
{
  export_out out;
  int st = export_begin(tubes, ntube, NULL, 0, opt, path, &out);
  if (st != CABLE_SUCCESS) return st;
  tube_mesh **m = out.m;
  FILE *f = out.f;
  long nv = 0, nf = 0;
  for (int k = 0; k < ntube; k++) nv += m[k]->nv, nf += m[k]->ntri;
  fprintf(f, "ply\nformat ascii 1.0\ncomment cable: tubes around the strands' centrelines\n");
  fprintf(f, "element vertex %ld\n", nv);
  fprintf(f, "property float x\nproperty float y\nproperty float z\n");
  fprintf(f, "property float nx\nproperty float ny\nproperty float nz\n");
  fprintf(f, "property uchar red\nproperty uchar green\nproperty uchar blue\n");
  fprintf(f, "property float quality\n");
  fprintf(f, "element face %ld\nproperty list uchar int vertex_indices\nend_header\n", nf);
  for (int k = 0; k < ntube; k++) {
    const double *rgb = tubes[k].rgb;
    for (int i = 0; i < m[k]->nv; i++) {
      const double *p = m[k]->xyz + 3 * i, *n = m[k]->normal + 3 * i;
      fprintf(f, EXPORT_PLY_FMT " " EXPORT_PLY_FMT " " EXPORT_PLY_FMT " " EXPORT_PLY_FMT " "
                 EXPORT_PLY_FMT " " EXPORT_PLY_FMT " %d %d %d " EXPORT_PLY_FMT "\n",
              p[0], p[1], p[2], n[0], n[1], n[2], ply_byte(rgb[0]), ply_byte(rgb[1]),
              ply_byte(rgb[2]), m[k]->scalar[i]);
    }
  }
  long base = 0;
  for (int k = 0; k < ntube; k++) {
    for (int i = 0; i < m[k]->ntri; i++) {
      const int *t = m[k]->tri + 3 * i;
      fprintf(f, "3 %ld %ld %ld\n", base + t[0], base + t[1], base + t[2]);
    }
    base += m[k]->nv;
  }
  return export_end(&out);
}
