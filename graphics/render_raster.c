/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Software z-buffer: triangles with per-sample normal interpolation, and
 * wide segments. */
#include "render_raster.h"

#include <math.h>
#include <stdlib.h>

#include "graphics_vec.h"

/* Lighting (camera coordinates: x right, y up, z into the picture).  A key
 * light from the upper left, in front of the picture, as in the paper's
 * figures; ambient keeps the unlit side readable, the specular highlight
 * shows the tubes' roundness. */
static const double render_light[3] = {-0.35, 0.55, -0.76};
#define RENDER_AMBIENT 0.25
#define RENDER_DIFFUSE 0.75
#define RENDER_SPECULAR 0.35
#define RENDER_SHININESS 40.0
/* Barycentric slack: samples on an edge shared by two triangles must not
 * fall through both because of round-off in the edge functions. */
#define RENDER_EDGE_SLACK 1e-9

render_zbuf *render_zbuf_alloc(int w, int h)
{
  if (w < 1 || h < 1) return NULL;
  render_zbuf *zb = calloc(1, sizeof *zb);
  if (zb == NULL) return NULL;
  zb->w = w, zb->h = h;
  zb->depth = malloc(sizeof(float) * (size_t)w * (size_t)h);
  zb->rgb = malloc(3 * (size_t)w * (size_t)h);
  if (zb->depth == NULL || zb->rgb == NULL) {
    render_zbuf_free(zb);
    return NULL;
  }
  return zb;
}

void render_zbuf_free(render_zbuf *zb)
{
  if (zb == NULL) return;
  free(zb->depth);
  free(zb->rgb);
  free(zb);
}

static unsigned char render_byte(double v)
{
  v = v < 0 ? 0 : v > 1 ? 1 : v;
  return (unsigned char)lround(255.0 * v);
}

void render_zbuf_clear(render_zbuf *zb, const double rgb[3])
{
  size_t n = (size_t)zb->w * (size_t)zb->h;
  for (size_t i = 0; i < n; i++) {
    zb->depth[i] = INFINITY;
    for (int a = 0; a < 3; a++) zb->rgb[3 * i + a] = render_byte(rgb[a]);
  }
}

void render_shade(const double n[3], const double rgb[3], double out[3])
{
  double l[3] = {render_light[0], render_light[1], render_light[2]};
  cable_vec3_normalize(l);
  double nn[3] = {n[0], n[1], n[2]};
  if (nn[2] > 0) nn[0] = -nn[0], nn[1] = -nn[1], nn[2] = -nn[2];
  double h[3] = {l[0], l[1], l[2] - 1.0}; /* half vector: light + eye (0, 0, -1) */
  cable_vec3_normalize(h);
  double diff = fmax(0.0, cable_vec3_dot(nn, l));
  double spec = RENDER_SPECULAR * pow(fmax(0.0, cable_vec3_dot(nn, h)), RENDER_SHININESS);
  for (int a = 0; a < 3; a++) out[a] = rgb[a] * (RENDER_AMBIENT + RENDER_DIFFUSE * diff) + spec;
}

static void render_put(render_zbuf *zb, size_t idx, double z, const double rgb[3])
{
  zb->depth[idx] = (float)z;
  for (int a = 0; a < 3; a++) zb->rgb[3 * idx + a] = render_byte(rgb[a]);
}

void render_zbuf_triangle(render_zbuf *zb, const render_vertex *a, const render_vertex *b,
                          const render_vertex *c)
{
  double area = (b->x - a->x) * (c->y - a->y) - (b->y - a->y) * (c->x - a->x);
  if (!(fabs(area) > 0)) return;
  int x0 = (int)floor(fmin(a->x, fmin(b->x, c->x))), x1 = (int)ceil(fmax(a->x, fmax(b->x, c->x)));
  int y0 = (int)floor(fmin(a->y, fmin(b->y, c->y))), y1 = (int)ceil(fmax(a->y, fmax(b->y, c->y)));
  if (x0 < 0) x0 = 0;
  if (y0 < 0) y0 = 0;
  if (x1 > zb->w - 1) x1 = zb->w - 1;
  if (y1 > zb->h - 1) y1 = zb->h - 1;
  for (int py = y0; py <= y1; py++) {
    double sy = py + 0.5;
    for (int px = x0; px <= x1; px++) {
      double sx = px + 0.5;
      double wa = ((b->x - sx) * (c->y - sy) - (b->y - sy) * (c->x - sx)) / area;
      double wb = ((c->x - sx) * (a->y - sy) - (c->y - sy) * (a->x - sx)) / area;
      double wc = 1.0 - wa - wb;
      if (wa < -RENDER_EDGE_SLACK || wb < -RENDER_EDGE_SLACK || wc < -RENDER_EDGE_SLACK) continue;
      double z = wa * a->z + wb * b->z + wc * c->z;
      size_t idx = (size_t)py * (size_t)zb->w + (size_t)px;
      if (!(z < (double)zb->depth[idx])) continue;
      double n[3], base[3], col[3];
      for (int k = 0; k < 3; k++) {
        n[k] = wa * a->n[k] + wb * b->n[k] + wc * c->n[k];
        base[k] = wa * a->rgb[k] + wb * b->rgb[k] + wc * c->rgb[k];
      }
      cable_vec3_normalize(n);
      render_shade(n, base, col);
      render_put(zb, idx, z, col);
    }
  }
}

void render_zbuf_segment(render_zbuf *zb, const double p0[3], const double p1[3], double width,
                         const double rgb[3], int overlay)
{
  double r = 0.5 * width, dx = p1[0] - p0[0], dy = p1[1] - p0[1];
  double len2 = dx * dx + dy * dy;
  int x0 = (int)floor(fmin(p0[0], p1[0]) - r), x1 = (int)ceil(fmax(p0[0], p1[0]) + r);
  int y0 = (int)floor(fmin(p0[1], p1[1]) - r), y1 = (int)ceil(fmax(p0[1], p1[1]) + r);
  if (x0 < 0) x0 = 0;
  if (y0 < 0) y0 = 0;
  if (x1 > zb->w - 1) x1 = zb->w - 1;
  if (y1 > zb->h - 1) y1 = zb->h - 1;
  for (int py = y0; py <= y1; py++)
    for (int px = x0; px <= x1; px++) {
      double sx = px + 0.5 - p0[0], sy = py + 0.5 - p0[1];
      double u = len2 > 0 ? (sx * dx + sy * dy) / len2 : 0.0;
      u = u < 0 ? 0 : u > 1 ? 1 : u;
      double ex = sx - u * dx, ey = sy - u * dy;
      if (ex * ex + ey * ey > r * r) continue;
      double z = p0[2] + u * (p1[2] - p0[2]);
      size_t idx = (size_t)py * (size_t)zb->w + (size_t)px;
      if (!(z < (double)zb->depth[idx])) continue;
      if (overlay) {
        for (int a = 0; a < 3; a++) zb->rgb[3 * idx + a] = render_byte(rgb[a]);
      } else {
        render_put(zb, idx, z, rgb);
      }
    }
}
