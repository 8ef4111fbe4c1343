/* SPDX-License-Identifier: GPL-3.0-or-later */
/* render_tubes_png: validation, meshing, rasterisation, profiles, colour
 * bar, PNG output. */
#include "render.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <cairo/cairo.h>

#include "cable/cable_status.h"
#include "graphics_file.h"
#include "graphics_vec.h"
#include "render_colormap.h"
#include "render_raster.h"
#include "tube_mesh.h"

/* Background: white, as the paper's figures. */
static const double render_background[3] = {1.0, 1.0, 1.0};
/* Ring facets about this many samples wide look round after shading;
 * at least 8 and at most 48 sides per ring. */
#define RENDER_FACET_SAMPLES 3.0
#define RENDER_SIDES_MIN 8
#define RENDER_SIDES_MAX 48
/* Profile line width in pixels: 3 px at 600 px and proportionally larger
 * in larger pictures; the contrasting outline adds RENDER_OUTLINE_PX a side. */
#define RENDER_PROFILE_PX 3.0
#define RENDER_PROFILE_REF_SIZE 600.0
#define RENDER_OUTLINE_PX 0.5
/* The profile is pulled towards the viewer by this many drawn tube radii:
 * one to reach the surface of the strands it lies between (the contact curve
 * is inside the thickened tubes), one more for the screen offset across the
 * tube's curved surface. */
#define RENDER_PROFILE_BIAS_RADII 2.0
/* Luminance above which a profile gets a dark outline (else a light one). */
#define RENDER_OUTLINE_LUMA 0.5

static int render_validate(const render_tube *tubes, int ntube, const render_profile *prof,
                           int nprof, const cable_render_options *opt, const char *path)
{
  if (tubes == NULL || ntube < 1 || path == NULL || path[0] == '\0') return CABLE_ERR_INPUT;
  if (nprof < 0 || (nprof > 0 && prof == NULL)) return CABLE_ERR_INPUT;
  if (opt && (opt->colormap < CABLE_RENDER_COLORMAP_NONE || opt->colormap > CABLE_RENDER_COLORMAP_DIVERGING ||
              !isfinite(opt->thicken)))
    return CABLE_ERR_INPUT;
  for (int k = 0; k < ntube; k++) {
    const render_tube *t = tubes + k;
    if (t->n < 2 || t->xyz == NULL || !(t->radius > 0) || !isfinite(t->radius)) return CABLE_ERR_INPUT;
    for (int i = 0; i < 3 * t->n; i++)
      if (!isfinite(t->xyz[i])) return CABLE_ERR_INPUT;
    if (t->scalar)
      for (int i = 0; i < t->n; i++)
        if (!isfinite(t->scalar[i])) return CABLE_ERR_INPUT;
    for (int a = 0; a < 3; a++)
      if (!isfinite(t->rgb[a])) return CABLE_ERR_INPUT;
  }
  for (int k = 0; k < nprof; k++) {
    const render_profile *p = prof + k;
    if (p->n < 2 || p->xyz == NULL || p->value == NULL || !isfinite(p->scale)) return CABLE_ERR_INPUT;
    for (int i = 0; i < p->n; i++)
      if (!isfinite(p->value[i]) || !isfinite(p->xyz[3 * i]) || !isfinite(p->xyz[3 * i + 1]) ||
          !isfinite(p->xyz[3 * i + 2]))
        return CABLE_ERR_INPUT;
  }
  return CABLE_SUCCESS;
}

/* Scalar range over the tubes that have one; 0 when none has. */
static int render_scalar_range(const render_tube *tubes, int ntube, double *vmin, double *vmax)
{
  int any = 0;
  *vmin = INFINITY, *vmax = -INFINITY;
  for (int k = 0; k < ntube; k++) {
    if (tubes[k].scalar == NULL) continue;
    any = 1;
    for (int i = 0; i < tubes[k].n; i++) {
      *vmin = fmin(*vmin, tubes[k].scalar[i]);
      *vmax = fmax(*vmax, tubes[k].scalar[i]);
    }
  }
  return any;
}

typedef struct {
  const render_camera *cam;
  int map;              /* colour map in use, or CABLE_RENDER_COLORMAP_NONE */
  double lo, hi;        /* scalar range of the map */
  double max_radius;    /* largest drawn radius (world units) */
} render_ctx;

static int render_tube_draw(render_zbuf *zb, const render_ctx *c, const render_tube *t)
{
  const render_camera *cam = c->cam;
  double ss = RENDER_SUPERSAMPLE, radius = t->radius * cam->thicken;
  int npts = tube_points_count(t->n, t->xyz, t->closed);
  int sides = (int)ceil(2.0 * GRAPHICS_PI * radius * cam->scale * ss / RENDER_FACET_SAMPLES);
  sides = sides < RENDER_SIDES_MIN ? RENDER_SIDES_MIN : sides > RENDER_SIDES_MAX ? RENDER_SIDES_MAX : sides;
  tube_mesh *m = tube_mesh_alloc(npts, sides, t->closed);
  render_vertex *v = m ? malloc(sizeof *v * (size_t)m->nv) : NULL;
  if (v == NULL) {
    tube_mesh_free(m);
    return CABLE_ERR_ALLOC;
  }
  int st = tube_mesh_build(m, t->xyz, t->scalar, radius);
  if (st == CABLE_SUCCESS) {
    int mapped = c->map != CABLE_RENDER_COLORMAP_NONE && t->scalar != NULL;
    for (int i = 0; i < m->nv; i++) {
      double x, y, z;
      const double *n = m->normal + 3 * i;
      render_camera_project(cam, m->xyz + 3 * i, &x, &y, &z);
      v[i].x = x * ss, v[i].y = y * ss, v[i].z = z;
      v[i].n[0] = cable_vec3_dot(n, cam->right), v[i].n[1] = cable_vec3_dot(n, cam->up);
      v[i].n[2] = cable_vec3_dot(n, cam->view);
      if (mapped) render_colormap_eval(c->map, (m->scalar[i] - c->lo) / (c->hi - c->lo), v[i].rgb);
      else memcpy(v[i].rgb, t->rgb, sizeof v[i].rgb);
    }
    for (int k = 0; k < m->ntri; k++) {
      const int *tri = m->tri + 3 * k;
      render_zbuf_triangle(zb, v + tri[0], v + tri[1], v + tri[2]);
    }
  }
  free(v);
  tube_mesh_free(m);
  return st;
}

/* Image-plane position (samples) and biased depth of profile point i. */
static void render_profile_point(const render_ctx *c, const render_profile *p, int i,
                                 double out[3])
{
  const render_camera *cam = c->cam;
  double ss = RENDER_SUPERSAMPLE, x, y, z, xa, ya, xb, yb, za;
  int ia = i > 0 ? i - 1 : i, ib = i < p->n - 1 ? i + 1 : i;
  render_camera_project(cam, p->xyz + 3 * i, &x, &y, &z);
  render_camera_project(cam, p->xyz + 3 * ia, &xa, &ya, &za);
  render_camera_project(cam, p->xyz + 3 * ib, &xb, &yb, &za);
  double tx = xb - xa, ty = yb - ya, tl = sqrt(tx * tx + ty * ty);
  /* screen normal: the tangent turned a quarter counter-clockwise on screen
   * (y grows downwards), so a positive value is drawn to the curve's left */
  double nx = tl > 0 ? ty / tl : 0.0, ny = tl > 0 ? -tx / tl : 0.0;
  double off = p->value[i] * p->scale * cam->scale;
  if (p->toward) {
    /* in 3-D: from the curve towards toward[i] (the strand), projected, so
       the profile follows the strand round the contact curve as the braid
       twists instead of jumping from one side to the other */
    const double *q = p->xyz + 3 * i, *t = p->toward + 3 * i;
    double d[3] = {t[0] - q[0], t[1] - q[1], t[2] - q[2]}, dl = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    double w[3];
    for (int k = 0; k < 3; k++) w[k] = q[k] + (dl > 0 ? p->value[i] * p->scale * d[k] / dl : 0.0);
    render_camera_project(cam, w, &x, &y, &z);
    off = 0;
  }
  out[0] = (x + off * nx) * ss;
  out[1] = (y + off * ny) * ss;
  out[2] = z - RENDER_PROFILE_BIAS_RADII * c->max_radius;
}

/* Pass 0 draws the profile's outline, pass 1 its line.  Profiles are
 * overlays: all outlines go first, then all lines, so every line shows
 * whole and a later profile is drawn over an earlier one. */
static void render_profile_draw(render_zbuf *zb, const render_ctx *c, const render_profile *p,
                                int pass)
{
  double ss = RENDER_SUPERSAMPLE;
  double w = RENDER_PROFILE_PX * fmax(1.0, c->cam->height / RENDER_PROFILE_REF_SIZE) * ss;
  for (int i = 0; i + 1 < p->n; i++) {
    double a[3], b[3];
    render_profile_point(c, p, i, a);
    render_profile_point(c, p, i + 1, b);
    /* a segment takes the colour of the sign at its midpoint */
    const double *rgb = p->value[i] + p->value[i + 1] >= 0 ? p->rgb_pos : p->rgb_neg;
    if (pass == 0) {
      double luma = 0.299 * rgb[0] + 0.587 * rgb[1] + 0.114 * rgb[2];
      double g = luma > RENDER_OUTLINE_LUMA ? 0.15 : 0.85, grey[3] = {g, g, g};
      render_zbuf_segment(zb, a, b, w + 2.0 * RENDER_OUTLINE_PX * ss, grey, 1);
    } else {
      render_zbuf_segment(zb, a, b, w, rgb, 1);
    }
  }
}

/* Average each RENDER_SUPERSAMPLE^2 block into the cairo image. */
static void render_resolve(const render_zbuf *zb, cairo_surface_t *s)
{
  int ss = RENDER_SUPERSAMPLE, w = cairo_image_surface_get_width(s);
  int h = cairo_image_surface_get_height(s), stride = cairo_image_surface_get_stride(s);
  unsigned char *data = cairo_image_surface_get_data(s);
  cairo_surface_flush(s);
  for (int y = 0; y < h; y++)
    for (int x = 0; x < w; x++) {
      unsigned sum[3] = {0, 0, 0};
      for (int j = 0; j < ss; j++)
        for (int i = 0; i < ss; i++) {
          size_t idx = (size_t)(y * ss + j) * (size_t)zb->w + (size_t)(x * ss + i);
          for (int a = 0; a < 3; a++) sum[a] += zb->rgb[3 * idx + a];
        }
      unsigned n = (unsigned)(ss * ss), px = 0xff000000u;
      px |= ((sum[0] + n / 2) / n) << 16 | ((sum[1] + n / 2) / n) << 8 | ((sum[2] + n / 2) / n);
      memcpy(data + (size_t)y * (size_t)stride + 4 * (size_t)x, &px, sizeof px);
    }
  cairo_surface_mark_dirty(s);
}

int render_tubes_png(const render_tube *tubes, int ntube, const render_profile *profiles,
                     int nprof, const cable_render_options *opt, const char *path)
{
  return render_tubes_png_text(tubes, ntube, profiles, nprof, opt, NULL, path);
}

int render_tubes_png_text(const render_tube *tubes, int ntube, const render_profile *profiles, int nprof,
                          const cable_render_options *opt, const render_text *text, const char *path)
{
  int st = render_validate(tubes, ntube, profiles, nprof, opt, path);
  if (st != CABLE_SUCCESS) return st;
  render_camera cam;
  if ((st = render_camera_fit(tubes, ntube, opt, &cam)) != CABLE_SUCCESS) return st;
  render_ctx c = {&cam, CABLE_RENDER_COLORMAP_NONE, 0, 1, 0};
  double vmin, vmax;
  if (opt && opt->colormap != CABLE_RENDER_COLORMAP_NONE && render_scalar_range(tubes, ntube, &vmin, &vmax)) {
    c.map = opt->colormap;
    render_colormap_range(c.map, vmin, vmax, &c.lo, &c.hi);
  }
  for (int k = 0; k < ntube; k++) c.max_radius = fmax(c.max_radius, tubes[k].radius * cam.thicken);

  render_zbuf *zb = render_zbuf_alloc(cam.width * RENDER_SUPERSAMPLE, cam.height * RENDER_SUPERSAMPLE);
  if (zb == NULL) return CABLE_ERR_ALLOC;
  render_zbuf_clear(zb, render_background);
  for (int k = 0; k < ntube && st == CABLE_SUCCESS; k++) st = render_tube_draw(zb, &c, tubes + k);
  for (int pass = 0; pass < 2 && st == CABLE_SUCCESS; pass++)
    for (int k = 0; k < nprof; k++) render_profile_draw(zb, &c, profiles + k, pass);
  if (st != CABLE_SUCCESS) {
    render_zbuf_free(zb);
    return st;
  }
  cairo_surface_t *s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, cam.width, cam.height);
  if (cairo_surface_status(s) == CAIRO_STATUS_SUCCESS) {
    render_resolve(zb, s);
    if (c.map != CABLE_RENDER_COLORMAP_NONE) {
      cairo_t *cr = cairo_create(s);
      render_colorbar_draw(cr, c.map, c.lo, c.hi, cam.plot_width, cam.width, cam.height,
                           text ? text->colorbar_title : NULL);
      if (cairo_status(cr) != CAIRO_STATUS_SUCCESS) st = CABLE_ERR_ALLOC;
      cairo_destroy(cr);
    }
    cairo_surface_flush(s);
    if (st == CABLE_SUCCESS) st = graphics_file_write_png_caption(s, path, text ? text->caption : NULL);
  } else {
    st = CABLE_ERR_ALLOC;
  }
  cairo_surface_destroy(s);
  render_zbuf_free(zb);
  return st;
}
