/* SPDX-License-Identifier: GPL-3.0-or-later */
/* VTK XML PolyData (ASCII) writer. */
#include <stdio.h>

#include "cable/cable_status.h"
#include "export_mesh.h"

/* Round-trip precision for doubles; normals need only float precision. */
#define EXPORT_VTP_FMT "%.17g"
#define EXPORT_VTP_NFMT "%.9g"

typedef struct {
  FILE *f;
  const render_tube *tubes;
  int ntube;
  const render_profile *curves;
  int ncurve;
  tube_mesh **m;
} vtp_ctx;

static void vtp_points(const vtp_ctx *c)
{
  FILE *f = c->f;
  fprintf(f, "      <Points>\n        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n");
  for (int k = 0; k < c->ntube; k++)
    for (int i = 0; i < c->m[k]->nv; i++) {
      const double *p = c->m[k]->xyz + 3 * i;
      fprintf(f, EXPORT_VTP_FMT " " EXPORT_VTP_FMT " " EXPORT_VTP_FMT "\n", p[0], p[1], p[2]);
    }
  for (int k = 0; k < c->ntube; k++)
    for (int i = 0; i < c->m[k]->npts; i++) {
      const double *p = c->tubes[k].xyz + 3 * i;
      fprintf(f, EXPORT_VTP_FMT " " EXPORT_VTP_FMT " " EXPORT_VTP_FMT "\n", p[0], p[1], p[2]);
    }
  for (int k = 0; k < c->ncurve; k++)
    for (int i = 0; i < c->curves[k].n; i++) {
      const double *p = c->curves[k].xyz + 3 * i;
      fprintf(f, EXPORT_VTP_FMT " " EXPORT_VTP_FMT " " EXPORT_VTP_FMT "\n", p[0], p[1], p[2]);
    }
  fprintf(f, "        </DataArray>\n      </Points>\n");
}

static void vtp_point_data(const vtp_ctx *c, const char *name)
{
  FILE *f = c->f;
  fprintf(f, "      <PointData Scalars=\"%s\" Normals=\"Normals\">\n", name);
  fprintf(f, "        <DataArray type=\"Float64\" Name=\"%s\" format=\"ascii\">\n", name);
  for (int k = 0; k < c->ntube; k++)
    for (int i = 0; i < c->m[k]->nv; i++) fprintf(f, EXPORT_VTP_FMT "\n", c->m[k]->scalar[i]);
  for (int k = 0; k < c->ntube; k++)
    for (int i = 0; i < c->m[k]->npts; i++)
      fprintf(f, EXPORT_VTP_FMT "\n", c->tubes[k].scalar ? c->tubes[k].scalar[i] : 0.0);
  for (int k = 0; k < c->ncurve; k++)
    for (int i = 0; i < c->curves[k].n; i++) fprintf(f, EXPORT_VTP_FMT "\n", c->curves[k].value[i]);
  fprintf(f, "        </DataArray>\n");

  fprintf(f, "        <DataArray type=\"Int32\" Name=\"part\" format=\"ascii\">\n");
  for (int k = 0; k < c->ntube; k++)
    for (int i = 0; i < c->m[k]->nv; i++) fprintf(f, "%d\n", k);
  for (int k = 0; k < c->ntube; k++)
    for (int i = 0; i < c->m[k]->npts; i++) fprintf(f, "%d\n", k);
  for (int k = 0; k < c->ncurve; k++)
    for (int i = 0; i < c->curves[k].n; i++) fprintf(f, "%d\n", c->ntube + k);
  fprintf(f, "        </DataArray>\n");

  fprintf(f, "        <DataArray type=\"Float32\" Name=\"Normals\" NumberOfComponents=\"3\" format=\"ascii\">\n");
  for (int k = 0; k < c->ntube; k++)
    for (int i = 0; i < c->m[k]->nv; i++) {
      const double *n = c->m[k]->normal + 3 * i;
      fprintf(f, EXPORT_VTP_NFMT " " EXPORT_VTP_NFMT " " EXPORT_VTP_NFMT "\n", n[0], n[1], n[2]);
    }
  for (int k = 0; k < c->ntube; k++)
    for (int i = 0; i < c->m[k]->npts; i++) fprintf(f, "0 0 0\n");
  for (int k = 0; k < c->ncurve; k++)
    for (int i = 0; i < c->curves[k].n; i++) fprintf(f, "0 0 0\n");
  fprintf(f, "        </DataArray>\n      </PointData>\n");
}

static void vtp_lines(const vtp_ctx *c, long base)
{
  FILE *f = c->f;
  fprintf(f, "      <Lines>\n        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n");
  long b = base;
  for (int k = 0; k < c->ntube; k++) {
    int n = c->m[k]->npts;
    for (int i = 0; i < n; i++) fprintf(f, "%ld\n", b + i);
    if (c->m[k]->closed) fprintf(f, "%ld\n", b);
    b += n;
  }
  for (int k = 0; k < c->ncurve; k++) {
    for (int i = 0; i < c->curves[k].n; i++) fprintf(f, "%ld\n", b + i);
    b += c->curves[k].n;
  }
  fprintf(f, "        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
  long off = 0;
  for (int k = 0; k < c->ntube; k++) {
    off += c->m[k]->npts + (c->m[k]->closed ? 1 : 0);
    fprintf(f, "%ld\n", off);
  }
  for (int k = 0; k < c->ncurve; k++) {
    off += c->curves[k].n;
    fprintf(f, "%ld\n", off);
  }
  fprintf(f, "        </DataArray>\n      </Lines>\n");
}

static void vtp_polys(const vtp_ctx *c)
{
  FILE *f = c->f;
  fprintf(f, "      <Polys>\n        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n");
  long b = 0;
  for (int k = 0; k < c->ntube; k++) {
    const tube_mesh *m = c->m[k];
    for (int i = 0; i < m->ntri; i++)
      fprintf(f, "%ld %ld %ld\n", b + m->tri[3 * i], b + m->tri[3 * i + 1], b + m->tri[3 * i + 2]);
    b += m->nv;
  }
  fprintf(f, "        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
  long off = 0;
  for (int k = 0; k < c->ntube; k++)
    for (int i = 0; i < c->m[k]->ntri; i++) fprintf(f, "%ld\n", off += 3);
  fprintf(f, "        </DataArray>\n      </Polys>\n");
}

int export_vtp_write(const render_tube *tubes, int ntube, const render_profile *curves,
                     int ncurve, const export_options *opt, const char *path)
{
  export_out out;
  int st = export_begin(tubes, ntube, curves, ncurve, opt, path, &out);
  if (st != CABLE_SUCCESS) return st;
  tube_mesh **m = out.m;
  vtp_ctx c = {out.f, tubes, ntube, curves, ncurve, m};
  long npoints = 0, nsurf = 0, npolys = 0;
  for (int k = 0; k < ntube; k++) {
    nsurf += m[k]->nv;
    npoints += m[k]->nv + m[k]->npts;
    npolys += m[k]->ntri;
  }
  for (int k = 0; k < ncurve; k++) npoints += curves[k].n;
  const char *name = opt && opt->scalar_name ? opt->scalar_name : "pressure";
  FILE *f = c.f;
  fprintf(f, "<?xml version=\"1.0\"?>\n");
  fprintf(f, "<!-- cable: tubes around the strands' centrelines, centrelines and contact curves -->\n");
  fprintf(f, "<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n  <PolyData>\n");
  fprintf(f, "    <Piece NumberOfPoints=\"%ld\" NumberOfVerts=\"0\" NumberOfLines=\"%d\" "
             "NumberOfStrips=\"0\" NumberOfPolys=\"%ld\">\n",
          npoints, ntube + ncurve, npolys);
  vtp_point_data(&c, name);
  vtp_points(&c);
  vtp_lines(&c, nsurf);
  vtp_polys(&c);
  fprintf(f, "    </Piece>\n  </PolyData>\n</VTKFile>\n");
  return export_end(&out);
}
