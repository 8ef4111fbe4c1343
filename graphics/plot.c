/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Bifurcation diagrams with cairo: layout, axes, branches, markers, legend. */
#include "plot.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cairo/cairo-svg.h>
#include <cairo/cairo.h>

#include "cable/cable_output.h"
#include "cable/cable_status.h"
#include "graphics_file.h"
#include "graphics_text.h"
#include "graphics_vec.h"
#include "plot_ticks.h"

/* Layout in units of the font size fs, so that a diagram scales with its
 * size: fs is the height divided by PLOT_FONT_DIVISOR, clamped to a range
 * that stays legible on screen and in print. */
#define PLOT_FONT_DIVISOR 30.0
#define PLOT_FONT_MIN 8.0
#define PLOT_FONT_MAX 22.0
#define PLOT_TICK_LEN 0.4      /* tick length */
#define PLOT_PAD 0.5           /* gap between ticks, labels and the edge */
#define PLOT_MARKER_R 0.32     /* marker radius */
#define PLOT_LINE_W 0.16       /* branch line width */
#define PLOT_DASH_ON 0.6       /* an unstable stretch's dashes and gaps */
#define PLOT_DASH_OFF 0.45
#define PLOT_LEGEND_ROW 1.4    /* legend row height */
#define PLOT_LEGEND_SAMPLE 2.0 /* legend line sample length */
/* About one tick interval per 90 pixels, between 3 and 10 intervals: fewer
 * gives too coarse a reading, more crowds the labels. */
#define PLOT_TICK_SPACING 90.0
#define PLOT_TICK_MIN 3
#define PLOT_TICK_MAX 10
/* Longest text drawn beside one marked point (several labels at one point
 * are joined; the rest is cut). */
#define PLOT_MARK_TEXT 96
/* A plot area smaller than this many font sizes a side cannot show data. */
#define PLOT_MIN_AREA 3.0

/* Tableau-10: distinct hues that stay apart in print and for most colour
 * vision deficiencies. */
static const double plot_palette[10][3] = {
    {0.122, 0.467, 0.706}, {1.000, 0.498, 0.055}, {0.173, 0.627, 0.173}, {0.839, 0.153, 0.157},
    {0.580, 0.404, 0.741}, {0.549, 0.337, 0.294}, {0.890, 0.467, 0.761}, {0.498, 0.498, 0.498},
    {0.737, 0.741, 0.133}, {0.090, 0.745, 0.812}};

void plot_branch_color(int i, double rgb[3])
{
  int k = ((i % 10) + 10) % 10;
  for (int j = 0; j < 3; j++) rgb[j] = plot_palette[k][j];
}

typedef struct {
  double left, top, pw, ph;   /* plot area in device units */
  plot_ticks tx, ty;
  double fs;
} plot_frame;

static double plot_px(const plot_frame *f, double x)
{
  return f->left + (x - f->tx.lo) / (f->tx.hi - f->tx.lo) * f->pw;
}

static double plot_py(const plot_frame *f, double y)
{
  return f->top + f->ph - (y - f->ty.lo) / (f->ty.hi - f->ty.lo) * f->ph;
}

static int plot_validate(const plot_branch *b, int nb, const cable_plot_annotation *an, int na,
                         const plot_options *opt, const char *path)
{
  if (b == NULL || nb < 1 || opt == NULL || path == NULL || path[0] == '\0') return CABLE_ERR_INPUT;
  if (na < 0 || (na > 0 && an == NULL)) return CABLE_ERR_INPUT;
  if (opt->format != PLOT_FORMAT_PNG && opt->format != PLOT_FORMAT_SVG) return CABLE_ERR_INPUT;
  if (opt->width > PLOT_MAX_SIZE || opt->height > PLOT_MAX_SIZE) return CABLE_ERR_INPUT;
  for (int i = 0; i < nb; i++)
    if (b[i].n < 1 || b[i].x == NULL || b[i].y == NULL) return CABLE_ERR_INPUT;
  return CABLE_SUCCESS;
}

/* Data range over every finite point and annotation; CABLE_ERR_INPUT when
 * there is none. */
static int plot_range(const plot_branch *b, int nb, const cable_plot_annotation *an, int na,
                      double lo[2], double hi[2])
{
  lo[0] = lo[1] = INFINITY;
  hi[0] = hi[1] = -INFINITY;
  for (int i = 0; i < nb; i++)
    for (int k = 0; k < b[i].n; k++) {
      double x = b[i].x[k], y = b[i].y[k];
      if (!isfinite(x) || !isfinite(y)) continue;
      lo[0] = fmin(lo[0], x), hi[0] = fmax(hi[0], x);
      lo[1] = fmin(lo[1], y), hi[1] = fmax(hi[1], y);
    }
  for (int i = 0; i < na; i++) {
    if (!isfinite(an[i].x) || !isfinite(an[i].y)) continue;
    lo[0] = fmin(lo[0], an[i].x), hi[0] = fmax(hi[0], an[i].x);
    lo[1] = fmin(lo[1], an[i].y), hi[1] = fmax(hi[1], an[i].y);
  }
  return lo[0] <= hi[0] ? CABLE_SUCCESS : CABLE_ERR_INPUT;
}

static int plot_tick_target(double pixels)
{
  int t = (int)(pixels / PLOT_TICK_SPACING);
  return t < PLOT_TICK_MIN ? PLOT_TICK_MIN : t > PLOT_TICK_MAX ? PLOT_TICK_MAX : t;
}

static int plot_layout(cairo_t *cr, const plot_options *opt, int w, int h, const double lo[2],
                       const double hi[2], plot_frame *f)
{
  char buf[64];
  f->fs = fmin(PLOT_FONT_MAX, fmax(PLOT_FONT_MIN, h / PLOT_FONT_DIVISOR));
  double fs = f->fs;
  if (plot_ticks_nice(lo[0], hi[0], plot_tick_target(w), &f->tx) != CABLE_SUCCESS ||
      plot_ticks_nice(lo[1], hi[1], plot_tick_target(h), &f->ty) != CABLE_SUCCESS)
    return CABLE_ERR_INPUT;
  graphics_text_font(cr, fs, 0);
  double wy = 0;
  for (int i = 0; i < f->ty.n; i++) {
    plot_ticks_format(&f->ty, plot_ticks_value(&f->ty, i), buf, sizeof buf);
    wy = fmax(wy, graphics_text_width(cr, buf));
  }
  plot_ticks_format(&f->tx, plot_ticks_value(&f->tx, f->tx.n - 1), buf, sizeof buf);
  double wlast = graphics_text_width(cr, buf);
  double pad = PLOT_PAD * fs, tick = PLOT_TICK_LEN * fs;
  f->left = pad + (opt->ylabel ? 1.5 * fs : 0) + wy + pad + tick;
  double bottom = tick + pad + fs + (opt->xlabel ? 1.6 * fs : 0) + pad;
  f->top = opt->title ? 2.4 * fs : 1.2 * fs;
  double right = fmax(1.2 * fs, 0.5 * wlast + pad);
  f->pw = w - f->left - right;
  f->ph = h - f->top - bottom;
  if (f->pw < PLOT_MIN_AREA * fs || f->ph < PLOT_MIN_AREA * fs) return CABLE_ERR_INPUT;
  return CABLE_SUCCESS;
}

static void plot_axes(cairo_t *cr, const plot_options *opt, int w, int h, const plot_frame *f)
{
  char buf[64];
  double fs = f->fs, tick = PLOT_TICK_LEN * fs, pad = PLOT_PAD * fs;
  double x0 = f->left, y0 = f->top, x1 = f->left + f->pw, y1 = f->top + f->ph;
  /* light grid first, so that data are drawn over it */
  cairo_set_line_width(cr, 0.06 * fs);
  cairo_set_source_rgb(cr, 0.88, 0.88, 0.88);
  for (int i = 0; i < f->tx.n; i++) {
    double x = plot_px(f, plot_ticks_value(&f->tx, i));
    cairo_move_to(cr, x, y0), cairo_line_to(cr, x, y1);
  }
  for (int i = 0; i < f->ty.n; i++) {
    double y = plot_py(f, plot_ticks_value(&f->ty, i));
    cairo_move_to(cr, x0, y), cairo_line_to(cr, x1, y);
  }
  cairo_stroke(cr);
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_set_line_width(cr, 0.08 * fs);
  cairo_rectangle(cr, x0, y0, f->pw, f->ph);
  cairo_stroke(cr);
  graphics_text_font(cr, fs, 0);
  for (int i = 0; i < f->tx.n; i++) {
    double v = plot_ticks_value(&f->tx, i), x = plot_px(f, v);
    cairo_move_to(cr, x, y1), cairo_line_to(cr, x, y1 + tick);
    cairo_stroke(cr);
    plot_ticks_format(&f->tx, v, buf, sizeof buf);
    graphics_text_show(cr, x, y1 + tick + pad, buf, 0.5, 0.0);
  }
  for (int i = 0; i < f->ty.n; i++) {
    double v = plot_ticks_value(&f->ty, i), y = plot_py(f, v);
    cairo_move_to(cr, x0 - tick, y), cairo_line_to(cr, x0, y);
    cairo_stroke(cr);
    plot_ticks_format(&f->ty, v, buf, sizeof buf);
    graphics_text_show(cr, x0 - tick - pad, y, buf, 1.0, 0.5);
  }
  if (opt->xlabel) graphics_text_show(cr, x0 + 0.5 * f->pw, h - pad, opt->xlabel, 0.5, 1.0);
  if (opt->ylabel) {
    cairo_save(cr);
    cairo_translate(cr, pad, y0 + 0.5 * f->ph);
    cairo_rotate(cr, -GRAPHICS_PI / 2);
    graphics_text_show(cr, 0, 0, opt->ylabel, 0.5, 0.0);
    cairo_restore(cr);
  }
  if (opt->title) {
    graphics_text_font(cr, 1.15 * fs, 1);
    graphics_text_show(cr, 0.5 * w, 0.6 * fs, opt->title, 0.5, 0.0);
  }
}

static void plot_lines(cairo_t *cr, const plot_branch *b, int nb, const plot_frame *f)
{
  cairo_save(cr);
  cairo_rectangle(cr, f->left, f->top, f->pw, f->ph);
  cairo_clip(cr);
  cairo_set_line_width(cr, PLOT_LINE_W * f->fs);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  for (int i = 0; i < nb; i++) {
    double rgb[3];
    plot_branch_color(i, rgb);
    cairo_set_source_rgb(cr, rgb[0], rgb[1], rgb[2]);
    int pen = 0, dash = 0;
    /* an unstable stretch (both ends unstable, plot_branch.unstable) is
       stroked dashed: the path is stroked whenever the style changes */
    double dl[2] = {PLOT_DASH_ON * f->fs, PLOT_DASH_OFF * f->fs};
    for (int k = 0; k < b[i].n; k++) {
      double x = b[i].x[k], y = b[i].y[k];
      if (!isfinite(x) || !isfinite(y)) {
        pen = 0;
        continue;
      }
      int d = b[i].unstable && k > 0 && b[i].unstable[k] && b[i].unstable[k - 1];
      if (d != dash) {
        if (pen) cairo_stroke(cr);
        cairo_set_dash(cr, dl, d ? 2 : 0, 0.0);
        if (pen) cairo_move_to(cr, plot_px(f, b[i].x[k - 1]), plot_py(f, b[i].y[k - 1]));
        dash = d;
      }
      if (pen) cairo_line_to(cr, plot_px(f, x), plot_py(f, y));
      else cairo_move_to(cr, plot_px(f, x), plot_py(f, y));
      pen = 1;
    }
    cairo_stroke(cr);
    cairo_set_dash(cr, dl, 0, 0.0);
  }
  cairo_restore(cr);
}

/* Marker shapes: a circle (filled: branch point, open: labelled point) or
 * an open triangle (a fold, AUTO's LP), r the circle's radius. */
enum { PLOT_MARK_OPEN = 0, PLOT_MARK_FILLED = 1, PLOT_MARK_FOLD = 2 };

static void plot_marker_at(cairo_t *cr, double px, double py, double r, int shape, double lw)
{
  cairo_new_path(cr);
  if (shape == PLOT_MARK_FOLD) {
    double t = 1.35 * r;   /* the triangle's area about the circle's */
    cairo_move_to(cr, px, py - t);
    cairo_line_to(cr, px + 0.866 * t, py + 0.5 * t);
    cairo_line_to(cr, px - 0.866 * t, py + 0.5 * t);
    cairo_close_path(cr);
  } else {
    cairo_arc(cr, px, py, r, 0, 2 * GRAPHICS_PI);
  }
  int filled = shape == PLOT_MARK_FILLED;
  cairo_set_source_rgb(cr, filled ? 0 : 1, filled ? 0 : 1, filled ? 0 : 1);
  cairo_fill_preserve(cr);
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_set_line_width(cr, lw);
  cairo_stroke(cr);
}

static int plot_is_fold(int type)
{
  int base = abs(type) % 10;
  return base == CABLE_TY_LP || base == 2;   /* 5: fold of a BVP, 2: of an ODE (AUTO's codes) */
}

static void plot_marker(cairo_t *cr, const plot_frame *f, double x, double y, int filled)
{
  double r = PLOT_MARKER_R * f->fs, px = plot_px(f, x), py = plot_py(f, y);
  if (filled == PLOT_MARK_FOLD) {
    plot_marker_at(cr, px, py, r, filled, 0.1 * f->fs);
    return;
  }
  cairo_new_path(cr);
  cairo_arc(cr, px, py, r, 0, 2 * GRAPHICS_PI);
  cairo_set_source_rgb(cr, filled ? 0 : 1, filled ? 0 : 1, filled ? 0 : 1);
  cairo_fill_preserve(cr);
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_set_line_width(cr, 0.1 * f->fs);
  cairo_stroke(cr);
}

/* A text box on the page: [x0, x1] x [y0, y1] in device units. */
typedef struct {
  double x0, y0, x1, y1;
} plot_box;

static int plot_box_overlap(const plot_box *a, const plot_box *b)
{
  return a->x0 < b->x1 && b->x0 < a->x1 && a->y0 < b->y1 && b->y0 < a->y1;
}

/* Draws a marker's text beside it, in the first of the four diagonal places
 * (above right, above left, below right, below left) that keeps the whole
 * text inside the plot area and clear of the texts placed before (placed[0..
 * nplaced-1]); failing that, the first place inside the plot area, so a mark
 * near the right or top edge keeps its label in the frame.  Returns the box
 * used. */
static plot_box plot_marker_text(cairo_t *cr, const plot_frame *f, double x, double y, const char *text,
                                 const plot_box *placed, int nplaced)
{
  double r = PLOT_MARKER_R * f->fs, off = 1.3 * r, px = plot_px(f, x), py = plot_py(f, y);
  graphics_text_font(cr, 0.9 * f->fs, 0);
  cairo_text_extents_t e;
  cairo_text_extents(cr, text, &e);
  const int right[4] = {1, 0, 1, 0}, up[4] = {1, 1, 0, 0};
  int inside_first = -1, chosen = -1;
  plot_box box[4];
  for (int k = 0; k < 4 && chosen < 0; k++) {
    box[k].x0 = right[k] ? px + off : px - off - e.width;
    box[k].x1 = box[k].x0 + e.width;
    box[k].y1 = up[k] ? py - off : py + off + e.height;
    box[k].y0 = box[k].y1 - e.height;
    int inside = box[k].x0 >= f->left && box[k].x1 <= f->left + f->pw && box[k].y0 >= f->top &&
                 box[k].y1 <= f->top + f->ph;
    if (!inside) continue;
    if (inside_first < 0) inside_first = k;
    int clear = 1;
    for (int i = 0; i < nplaced && clear; i++) clear = !plot_box_overlap(&box[k], &placed[i]);
    if (clear) chosen = k;
  }
  if (chosen < 0) chosen = inside_first >= 0 ? inside_first : 0;
  graphics_text_show(cr, right[chosen] ? px + off : px - off, up[chosen] ? py - off : py + off, text,
                     right[chosen] ? 0.0 : 1.0, up[chosen] ? 1.0 : 0.0);
  return box[chosen];
}

/* A marked point: its pixel position and its text (one of the markers at a
 * pixel position carries the texts of all of them). */
typedef struct {
  double px, py, x, y;
  char text[PLOT_MARK_TEXT];
} plot_mark;

/* Adds the text of a mark at (x, y) to marks[]: appended to an earlier mark
 * within a marker radius on screen (branches that start at one point, e.g.
 * both arms of a flat branch, label it twice: "1, 7" instead of two labels
 * drawn over each other), else a new entry.  Returns the new count. */
static int plot_mark_add(plot_mark *marks, int n, int cap, const plot_frame *f, double x, double y, const char *text)
{
  double px = plot_px(f, x), py = plot_py(f, y), r = PLOT_MARKER_R * f->fs;
  for (int i = 0; i < n; i++)
    if (fabs(marks[i].px - px) <= r && fabs(marks[i].py - py) <= r) {
      size_t len = strlen(marks[i].text);
      snprintf(marks[i].text + len, sizeof marks[i].text - len, "%s%s", len ? ", " : "", text);
      return n;
    }
  if (n >= cap) return n;
  marks[n] = (plot_mark){px, py, x, y, ""};
  snprintf(marks[n].text, sizeof marks[n].text, "%s", text);
  return n + 1;
}

/* Draws the markers, then their texts; *boxes (may be NULL when out of
 * memory) receives the texts' boxes for the legend to keep clear of; returns
 * their number. */
static int plot_markers(cairo_t *cr, const plot_branch *b, int nb, const cable_plot_annotation *an, int na,
                        const plot_frame *f, plot_box **boxes)
{
  char buf[32];
  int cap = na;
  for (int i = 0; i < nb; i++)
    for (int k = 0; k < b[i].n; k++) cap += b[i].label && b[i].label[k] != 0;
  plot_mark *marks = cap > 0 ? malloc((size_t)cap * sizeof *marks) : NULL;
  *boxes = cap > 0 ? malloc((size_t)cap * sizeof **boxes) : NULL;
  int nm = 0;
  for (int i = 0; i < nb; i++)
    for (int k = 0; k < b[i].n; k++) {
      double x = b[i].x[k], y = b[i].y[k];
      if (!isfinite(x) || !isfinite(y)) continue;
      int bp = b[i].type && b[i].type[k] == CABLE_TY_BP;
      int fold = b[i].type && plot_is_fold(b[i].type[k]);
      int lab = b[i].label ? b[i].label[k] : 0;
      if (!bp && !fold && lab == 0) continue;
      plot_marker(cr, f, x, y, fold ? PLOT_MARK_FOLD : bp);
      if (lab != 0) {
        snprintf(buf, sizeof buf, "%d", lab);
        if (marks) nm = plot_mark_add(marks, nm, cap, f, x, y, buf);
        else plot_marker_text(cr, f, x, y, buf, NULL, 0); /* out of memory: no joining or avoidance */
      }
    }
  for (int i = 0; i < na; i++)
    if (isfinite(an[i].x) && isfinite(an[i].y)) {
      plot_marker(cr, f, an[i].x, an[i].y, an[i].filled);
      if (!an[i].text || !an[i].text[0]) continue;
      if (marks) nm = plot_mark_add(marks, nm, cap, f, an[i].x, an[i].y, an[i].text);
      else plot_marker_text(cr, f, an[i].x, an[i].y, an[i].text, NULL, 0);
    }
  /* the annotations (a scene's named points) first: they get the best places */
  int nbox = 0;
  plot_box tmp;
  for (int pass = 0; pass < 2; pass++)
    for (int i = 0; i < nm; i++) {
      int is_annot = !(marks[i].text[0] >= '0' && marks[i].text[0] <= '9');
      if (is_annot != (pass == 0)) continue;
      tmp = plot_marker_text(cr, f, marks[i].x, marks[i].y, marks[i].text, *boxes, *boxes ? nbox : 0);
      if (*boxes) (*boxes)[nbox++] = tmp;
    }
  free(marks);
  return *boxes ? nbox : 0;
}

/* A text label under the legend costs as much as this many hidden data
 * points: a label is read, a few points of a line are not missed. */
#define PLOT_LEGEND_LABEL_COST 1000

/* Data points, plus labels at PLOT_LEGEND_LABEL_COST each, that a legend box
 * at (x, y, w, h) would hide. */
static long plot_hidden(const plot_branch *b, int nb, const plot_box *boxes, int nbox, const plot_frame *f,
                        double x, double y, double w, double h)
{
  long c = 0;
  for (int i = 0; i < nb; i++)
    for (int k = 0; k < b[i].n; k++) {
      if (!isfinite(b[i].x[k]) || !isfinite(b[i].y[k])) continue;
      double px = plot_px(f, b[i].x[k]), py = plot_py(f, b[i].y[k]);
      c += px >= x && px <= x + w && py >= y && py <= y + h;
    }
  plot_box lg = {x, y, x + w, y + h};
  for (int i = 0; i < nbox; i++) c += PLOT_LEGEND_LABEL_COST * plot_box_overlap(&lg, &boxes[i]);
  return c;
}

/* The marker shapes the diagram shows, for the legend's key: [0] branch
 * points, [1] folds; [2] (open circles) stays 0: they carry their label or
 * text beside them and need no key. */
static void plot_shapes_used(const plot_branch *b, int nb, const cable_plot_annotation *an, int na, int used[3])
{
  used[0] = used[1] = used[2] = 0;
  for (int i = 0; i < nb; i++)
    for (int k = 0; k < b[i].n; k++) {
      int t = b[i].type ? b[i].type[k] : 0;
      if (!isfinite(b[i].x[k]) || !isfinite(b[i].y[k])) continue;
      if (t == CABLE_TY_BP) used[0] = 1;
      else if (b[i].type && plot_is_fold(t)) used[1] = 1;
    }
  for (int i = 0; i < na; i++) used[0] |= an[i].filled != 0;
}

static const char *const plot_shape_names[3] = {"branch point", "fold", "labelled point"};

static void plot_legend(cairo_t *cr, const plot_branch *b, int nb, const cable_plot_annotation *an, int na,
                        const plot_box *boxes, int nbox, const plot_frame *f)
{
  char buf[32];
  double fs = f->fs, row = PLOT_LEGEND_ROW * fs, sample = PLOT_LEGEND_SAMPLE * fs;
  graphics_text_font(cr, 0.9 * fs, 0);
  double tw = 0;
  int used[3], nkey = 0;
  plot_shapes_used(b, nb, an, na, used);
  for (int i = 0; i < nb; i++) {
    snprintf(buf, sizeof buf, "branch %d", i + 1);
    tw = fmax(tw, graphics_text_width(cr, b[i].name ? b[i].name : buf));
  }
  for (int k = 0; k < 3; k++)
    if (used[k]) {
      nkey++;
      tw = fmax(tw, graphics_text_width(cr, plot_shape_names[k]));
    }
  double w = sample + tw + 1.5 * fs, h = (nb + nkey) * row + 0.4 * fs, m = 0.5 * fs;
  /* the corner that hides the fewest data points and labels; top right on a tie */
  const double cx[4] = {f->left + f->pw - m - w, f->left + m, f->left + f->pw - m - w, f->left + m};
  const double cy[4] = {f->top + m, f->top + m, f->top + f->ph - m - h, f->top + f->ph - m - h};
  int best = 0;
  long hid = plot_hidden(b, nb, boxes, nbox, f, cx[0], cy[0], w, h);
  for (int c = 1; c < 4; c++) {
    long hc = plot_hidden(b, nb, boxes, nbox, f, cx[c], cy[c], w, h);
    if (hc < hid) hid = hc, best = c;
  }
  double x = cx[best], y = cy[best];
  cairo_rectangle(cr, x, y, w, h);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_fill_preserve(cr);
  cairo_set_source_rgb(cr, 0.3, 0.3, 0.3);
  cairo_set_line_width(cr, 0.06 * fs);
  cairo_stroke(cr);
  for (int i = 0; i < nb; i++) {
    double rgb[3], yc = y + 0.2 * fs + (i + 0.5) * row;
    plot_branch_color(i, rgb);
    cairo_set_source_rgb(cr, rgb[0], rgb[1], rgb[2]);
    cairo_set_line_width(cr, PLOT_LINE_W * fs * 1.5);
    cairo_move_to(cr, x + 0.5 * fs, yc), cairo_line_to(cr, x + 0.5 * fs + sample - 0.5 * fs, yc);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    snprintf(buf, sizeof buf, "branch %d", i + 1);
    graphics_text_show(cr, x + sample + 0.5 * fs, yc, b[i].name ? b[i].name : buf, 0.0, 0.5);
  }
  /* the key of the marks under the branches */
  static const int shape[3] = {PLOT_MARK_FILLED, PLOT_MARK_FOLD, PLOT_MARK_OPEN};
  for (int k = 0, r = nb; k < 3; k++) {
    if (!used[k]) continue;
    double yc = y + 0.2 * fs + (r + 0.5) * row;
    plot_marker_at(cr, x + 0.5 * fs + 0.5 * (sample - 0.5 * fs), yc, PLOT_MARKER_R * fs, shape[k], 0.1 * fs);
    cairo_set_source_rgb(cr, 0, 0, 0);
    graphics_text_show(cr, x + sample + 0.5 * fs, yc, plot_shape_names[k], 0.0, 0.5);
    r++;
  }
}

static void plot_draw(cairo_t *cr, const plot_branch *b, int nb, const cable_plot_annotation *an,
                      int na, const plot_options *opt, int w, int h, const plot_frame *f)
{
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  plot_axes(cr, opt, w, h, f);
  plot_lines(cr, b, nb, f);
  plot_box *boxes = NULL;
  int nbox = plot_markers(cr, b, nb, an, na, f, &boxes);
  plot_legend(cr, b, nb, an, na, boxes, nbox, f);
  free(boxes);
}

int plot_bifurcation_annotated(const plot_branch *branches, int nbranch,
                               const cable_plot_annotation *annot, int nannot,
                               const plot_options *opt, const char *path)
{
  return plot_bifurcation_captioned(branches, nbranch, annot, nannot, opt, NULL, path);
}

int plot_bifurcation_captioned(const plot_branch *branches, int nbranch, const cable_plot_annotation *annot, int nannot,
                               const plot_options *opt, const char *caption, const char *path)
{
  int st = plot_validate(branches, nbranch, annot, nannot, opt, path);
  if (st != CABLE_SUCCESS) return st;
  double lo[2], hi[2];
  if ((st = plot_range(branches, nbranch, annot, nannot, lo, hi)) != CABLE_SUCCESS) return st;
  int w = opt->width > 0 ? opt->width : PLOT_DEFAULT_WIDTH;
  int h = opt->height > 0 ? opt->height : PLOT_DEFAULT_HEIGHT;

  cable_atomic_file *file = NULL;
  cairo_surface_t *s;
  if (opt->format == PLOT_FORMAT_SVG) {
    if ((file = cable_atomic_open(path, 0, NULL)) == NULL) return CABLE_ERR_IO;
    s = cairo_svg_surface_create_for_stream(graphics_file_cairo_write, file, w, h);
  } else {
    s = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, w, h);
  }
  cairo_t *cr = cairo_create(s);
  plot_frame f;
  st = plot_layout(cr, opt, w, h, lo, hi, &f);
  if (st == CABLE_SUCCESS) {
    plot_draw(cr, branches, nbranch, annot, nannot, opt, w, h, &f);
    if (cairo_status(cr) != CAIRO_STATUS_SUCCESS) st = CABLE_ERR_ALLOC;
  }
  cairo_destroy(cr);
  if (opt->format == PLOT_FORMAT_SVG) {
    cairo_surface_finish(s);  /* writes the rest of the document */
    if (st == CABLE_SUCCESS && cairo_surface_status(s) != CAIRO_STATUS_SUCCESS) st = CABLE_ERR_IO;
    cairo_surface_destroy(s);
    if (st == CABLE_SUCCESS) st = cable_atomic_commit(file, NULL);
    else cable_atomic_abort(file);
    return st;
  }
  if (st == CABLE_SUCCESS) {
    cairo_surface_flush(s);
    st = cairo_surface_status(s) == CAIRO_STATUS_SUCCESS ? graphics_file_write_png_caption(s, path, caption)
                                                         : CABLE_ERR_ALLOC;
  }
  cairo_surface_destroy(s);
  return st;
}

int plot_bifurcation(const plot_branch *branches, int nbranch, const plot_options *opt,
                     const char *path)
{
  return plot_bifurcation_annotated(branches, nbranch, NULL, 0, opt, path);
}
