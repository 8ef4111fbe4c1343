/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Colour maps and colour bar. */
#include "render_colormap.h"

#include <math.h>
#include <stdio.h>

#include "graphics_text.h"
#include "plot_ticks.h"
#include "render.h"

/* viridis (perceptually uniform, readable in grey scale) at u = k/8 */
static const double render_viridis[9][3] = {
    {0.267, 0.005, 0.329}, {0.282, 0.157, 0.471}, {0.243, 0.290, 0.537},
    {0.192, 0.408, 0.557}, {0.149, 0.510, 0.557}, {0.122, 0.620, 0.537},
    {0.208, 0.718, 0.475}, {0.427, 0.804, 0.349}, {0.992, 0.906, 0.145}};
/* Moreland's cool-warm diverging map at u = k/4: sign changes of the contact
 * pressure (cable links, Figs. 12.7-12.9) show as blue against red */
static const double render_coolwarm[5][3] = {{0.230, 0.299, 0.754}, {0.552, 0.690, 0.996},
                                             {0.865, 0.865, 0.865}, {0.958, 0.604, 0.482},
                                             {0.706, 0.016, 0.150}};

/* Colour bar layout, in fractions of the reserved strip and picture height;
 * the strip is a sixth of the width but at least RENDER_BAR_MIN_PX so that
 * tick labels fit in small pictures. */
#define RENDER_BAR_FRACTION 0.16
#define RENDER_BAR_MIN_PX 56
#define RENDER_BAR_TOP 0.12
#define RENDER_BAR_BOTTOM 0.88
#define RENDER_BAR_TICKS 5
/* A tick within round-off of the bar's ends belongs on the bar. */
#define RENDER_BAR_TICK_SLACK 1e-9

static void render_table(const double (*tab)[3], int n, double u, double rgb[3])
{
  u = fmin(1.0, fmax(0.0, u)) * (n - 1);
  int k = (int)floor(u);
  if (k >= n - 1) k = n - 2;
  double f = u - k;
  for (int a = 0; a < 3; a++) rgb[a] = (1 - f) * tab[k][a] + f * tab[k + 1][a];
}

void render_colormap_eval(int map, double u, double rgb[3])
{
  if (map == CABLE_RENDER_COLORMAP_DIVERGING) render_table(render_coolwarm, 5, u, rgb);
  else render_table(render_viridis, 9, u, rgb);
}

void render_colormap_range(int map, double vmin, double vmax, double *lo, double *hi)
{
  if (map == CABLE_RENDER_COLORMAP_DIVERGING) {
    double m = fmax(fabs(vmin), fabs(vmax));
    *lo = -m, *hi = m;
  } else {
    *lo = vmin, *hi = vmax;
  }
  if (!(*hi > *lo)) {
    double d = fabs(*lo) > 0 ? 0.1 * fabs(*lo) : 1.0;
    *lo -= d, *hi += d;
  }
}

int render_colorbar_width(int width, int height)
{
  (void)height;
  int w = (int)(RENDER_BAR_FRACTION * width);
  return w < RENDER_BAR_MIN_PX ? RENDER_BAR_MIN_PX : w;
}

void render_colorbar_draw(cairo_t *cr, int map, double lo, double hi, double x0, int width,
                          int height, const char *title)
{
  double strip = width - x0;
  double fs = fmin(16.0, fmax(7.0, height / 40.0));
  double bx = x0 + 0.08 * strip, bw = fmax(6.0, 0.2 * strip);
  double y0 = RENDER_BAR_TOP * height, y1 = RENDER_BAR_BOTTOM * height;
  int rows = (int)ceil(y1 - y0);
  for (int r = 0; r < rows; r++) {
    double rgb[3];
    render_colormap_eval(map, 1.0 - (r + 0.5) / rows, rgb);
    cairo_set_source_rgb(cr, rgb[0], rgb[1], rgb[2]);
    cairo_rectangle(cr, bx, y0 + r, bw, 1.0);
    cairo_fill(cr);
  }
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_set_line_width(cr, 1.0);
  cairo_rectangle(cr, bx, y0, bw, y1 - y0);
  cairo_stroke(cr);
  if (title && title[0]) {
    /* the title above the bar, right-aligned to the picture's edge when it
       is wider than the strip */
    graphics_text_font(cr, fs, 0);
    double tw = graphics_text_width(cr, title);
    double tx = fmin(bx, width - 0.3 * fs - tw);
    graphics_text_show(cr, tx, y0 - 0.6 * fs, title, 0.0, 1.0);
  }
  plot_ticks t;
  if (plot_ticks_nice(lo, hi, RENDER_BAR_TICKS, &t) != 0) return;
  graphics_text_font(cr, fs, 0);
  char buf[64];
  for (int i = 0; i < t.n; i++) {
    double v = plot_ticks_value(&t, i);
    if (v < lo - RENDER_BAR_TICK_SLACK * t.step || v > hi + RENDER_BAR_TICK_SLACK * t.step)
      continue;
    double y = y1 - (v - lo) / (hi - lo) * (y1 - y0);
    cairo_move_to(cr, bx + bw, y), cairo_line_to(cr, bx + bw + 0.3 * fs, y);
    cairo_stroke(cr);
    plot_ticks_format(&t, v, buf, sizeof buf);
    graphics_text_show(cr, bx + bw + 0.5 * fs, y, buf, 0.0, 0.5);
  }
}
