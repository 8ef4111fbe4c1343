/* SPDX-License-Identifier: GPL-3.0-or-later */
#include "cable/cable_pictures.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cable/cable_analysis.h"
#include "cable/cable_aufile.h"
#include "cable/cable_names.h"
#include "graphics_text.h"
#include "braid_model.h"
#include "braid_pressure.h"
#include "braid_state.h"
#include "cable/cable_status.h"
#include "export.h"
#include "plot.h"
#include "render.h"

#define PLOT_MAX_BRANCHES 256

static int has_suffix(const char *s, const char *suf)
{
  size_t a = strlen(s), b = strlen(suf);
  return a >= b && strcmp(s + a - b, suf) == 0;
}

/* A picture's format follows its file name: a .svg name holding PNG bytes
 * (or the reverse) is refused before anything is written.  Returns 0 or
 * CABLE_ERR_INPUT with err naming the file and the option. */
static int check_suffix(const char *path, const char *key, const char *const *suf, int nsuf, cable_error *err)
{
  for (int i = 0; i < nsuf; i++)
    if (has_suffix(path, suf[i])) return 0;
  char list[64] = "";
  for (int i = 0; i < nsuf; i++)
    snprintf(list + strlen(list), sizeof list - strlen(list), "%s%s", i ? " or " : "", suf[i]);
  return cable_error_set(err, CABLE_ERR_INPUT, path, 0, key, "the file name must end in %s (the format it is written in)",
                         list);
}

static int same_point(double x1, double y1, double x2, double y2)
{
  return fabs(x1 - x2) <= 1e-9 * (1 + fabs(x1)) && fabs(y1 - y2) <= 1e-9 * (1 + fabs(y1));
}

/* The diagram's caption: title, axes, branches and what the marks mean, in one line. */
static void plot_caption(const char *title, const char *x, const char *y, const plot_branch *b, int nb, char *buf,
                         size_t n)
{
  size_t k = (size_t)snprintf(buf, n, "%s%scable plot: %s against %s; branches:", title ? title : "",
                              title ? ". " : "", y, x);
  for (int i = 0; i < nb && k < n; i++) k += (size_t)snprintf(buf + k, n - k, "%s %s", i ? "," : "", b[i].name);
  if (k < n)
    snprintf(buf + k, n - k, "; filled circles: branch points, triangles: folds, open circles: labelled points");
  for (char *p = buf; *p; p++)
    if (*p == '\n' || *p == '\r') *p = ' ';   /* one line (a title may hold a newline) */
}

int cable_plot_files(const char *dir, const char *const *bfiles, int nfiles, const char *xcol, const char *ycol,
                     const cable_plot_annotation *marks, int nmarks, const char *title, const char *out,
                     cable_error *err)
{
  static const char *const plot_suffixes[2] = {".png", ".svg"};
  cable_error local;
  if (!err) err = &local;   /* the function reads err->status below */
  if (!out) return cable_error_set(err, CABLE_ERR_NULL, NULL, 0, "o", "no output file (NULL)");
  if (check_suffix(out, "o", plot_suffixes, 2, err)) return err->status;
  if (nfiles < 1 || nfiles > 64) return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, "", "give 1 to 64 b-files");
  if (!bfiles) return cable_error_set(err, CABLE_ERR_NULL, NULL, 0, "", "no b-file names (NULL)");
  for (int f = 0; f < nfiles; f++)
    if (!bfiles[f]) return cable_error_set(err, CABLE_ERR_NULL, NULL, 0, "", "b-file name %d is NULL", f + 1);
  if (nmarks > 0 && !marks) return cable_error_set(err, CABLE_ERR_NULL, NULL, 0, "", "%d marks but no array", nmarks);
  cable_bfile *files[64] = {NULL};
  plot_branch br[PLOT_MAX_BRANCHES];
  char names[PLOT_MAX_BRANCHES][64];
  int *labels[PLOT_MAX_BRANCHES], *types[PLOT_MAX_BRANCHES];
  int nb = 0, rc = 0;
  const char *xl = xcol, *yl = ycol;
  for (int f = 0; f < nfiles && !rc; f++) {
    char path[1200];
    snprintf(path, sizeof path, "%s%s%s", dir && dir[0] ? dir : "", dir && dir[0] ? "/" : "", bfiles[f]);
    if (!(files[f] = cable_bfile_read(path, err))) {
      rc = err->status ? err->status : CABLE_ERR_IO;
      break;
    }
    const char *base = strrchr(bfiles[f], '/');
    base = base ? base + 1 : bfiles[f];
    if (strncmp(base, "b.", 2) == 0) base += 2;
    for (int s = 0; s < files[f]->nbranch && nb < PLOT_MAX_BRANCHES; s++) {
      const cable_bfile_branch *b = &files[f]->branch[s];
      if (b->nrow < 1) continue;
      /* defaults: the principal parameter against F when present, else L2-NORM */
      const char *xc = xcol ? xcol : b->colname[0];
      const char *yc = ycol ? ycol : cable_bfile_column(b, "F") ? "F" : "L2-NORM";
      const double *x = cable_bfile_column(b, xc), *y = cable_bfile_column(b, yc);
      if (!x || !y) {
        rc = cable_error_set(err, CABLE_ERR_NOTFOUND, path, b->first_line, !x ? xc : yc,
                             "no such column in branch %d of this b-file", abs(b->br[0]));
        break;
      }
      labels[nb] = malloc(3 * (size_t)b->nrow * sizeof(int));
      if (!labels[nb]) {
        rc = cable_error_set(err, CABLE_ERR_ALLOC, NULL, 0, "", "out of memory");
        break;
      }
      types[nb] = labels[nb] + b->nrow;
      int *unstable = b->stab ? labels[nb] + 2 * b->nrow : NULL;   /* STAB=1: PT > 0 is unstable */
      for (int i = 0; i < b->nrow; i++) {
        labels[nb][i] = cable_type_base(b->ty[i]) == 4 ? 0 : b->lab[i];
        types[nb][i] = b->ty[i];
        if (unstable) unstable[i] = b->pt[i] > 0;
      }
      xl = xc;
      yl = yc;
      if (files[f]->nbranch > 1) snprintf(names[nb], sizeof names[nb], "%s (%d)", base, s + 1);
      else snprintf(names[nb], sizeof names[nb], "%s", base);
      br[nb] = (plot_branch){names[nb], b->nrow, x, y, types[nb], labels[nb], unstable};
      nb++;
    }
  }
  int any_filled = 0;
  for (int m = 0; m < nmarks; m++) any_filled |= marks[m].filled != 0;
  /* a point that sits on a branch point of another branch (a branch's start
     at the BP it was switched from) or on a mark is drawn only once: as the
     BP or the mark */
  for (int i = 0; !rc && i < nb; i++)
    for (int k = 0; k < br[i].n; k++) {
      /* a scene that numbers branch points itself (filled marks: the paper's
         "1".."4") replaces their AUTO labels: every branch point keeps its
         circle, only the scene's numbers are written */
      if (cable_type_base(types[i][k]) == 6 && any_filled) labels[i][k] = 0;
      if (cable_type_base(types[i][k]) == 6 || !labels[i][k]) continue;
      int hidden = 0;
      for (int m = 0; m < nmarks; m++) hidden |= same_point(br[i].x[k], br[i].y[k], marks[m].x, marks[m].y);
      for (int j = 0; !hidden && j < nb; j++)
        for (int q = 0; !hidden && q < br[j].n; q++)
          hidden = cable_type_base(types[j][q]) == 6 && same_point(br[i].x[k], br[i].y[k], br[j].x[q], br[j].y[q]);
      if (hidden) {
        labels[i][k] = 0;
        types[i][k] = 0;
      }
    }
  if (!rc && nb == 0) rc = cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, "", "the b-files hold no points");
  if (!rc) {
    plot_options o = {xl, yl, title, 0, 0, has_suffix(out, ".svg") ? PLOT_FORMAT_SVG : PLOT_FORMAT_PNG};
    char caption[1000];
    plot_caption(title, xl, yl, br, nb, caption, sizeof caption);
    rc = plot_bifurcation_captioned(br, nb, marks, nmarks, &o, caption, out);
    if (rc) cable_error_set(err, rc, out, 0, "o", "cannot write the diagram: %s", cable_status_message(rc));
  }
  for (int i = 0; i < nb; i++) free(labels[i]);
  for (int f = 0; f < nfiles; f++) cable_bfile_free(files[f]);
  return rc;
}

/* Strands, contact curve and pressures of a braid solution at its nodes. */
typedef struct {
  int n;
  double *r1, *r2, *c, *p1, *p2;
} braid_picture;

static void picture_free(braid_picture *bp)
{
  free(bp->r1); free(bp->r2); free(bp->c); free(bp->p1); free(bp->p2);
}

static int picture_build(const cable_solution *s, braid_picture *bp)
{
  int n = cable_solution_npts(s);
  memset(bp, 0, sizeof *bp);
  bp->n = n;
  bp->r1 = malloc(3 * (size_t)n * sizeof(double));
  bp->r2 = malloc(3 * (size_t)n * sizeof(double));
  bp->c = malloc(3 * (size_t)n * sizeof(double));
  bp->p1 = malloc((size_t)n * sizeof(double));
  bp->p2 = malloc((size_t)n * sizeof(double));
  if (!bp->r1 || !bp->r2 || !bp->c || !bp->p1 || !bp->p2) return CABLE_ERR_ALLOC;
  braid_material m;
  braid_material_from_par(s->par, &m);
  double delta = s->par[BP_DELTA];
  for (int k = 0; k < n; k++) {
    const double *u = s->u + (size_t)k * BR_NDIM;
    double q0 = u[BR_Q0], q1 = u[BR_Q1], q2 = u[BR_Q2], q3 = u[BR_Q3];
    double qq = q0 * q0 + q1 * q1 + q2 * q2 + q3 * q3;
    /* d1 from the Euler parameters (paper, Sect. 12.2.3), normalised by |q|^2 */
    double d1[3] = {(2 * q1 * q2 - 2 * q0 * q3) / qq, (q0 * q0 - q1 * q1 + q2 * q2 - q3 * q3) / qq,
                    (2 * q2 * q3 + 2 * q0 * q1) / qq};
    for (int i = 0; i < 3; i++) {
      bp->r1[3 * k + i] = u[BR_X1 + i];
      bp->r2[3 * k + i] = u[BR_X1 + i] + delta * d1[i];
      bp->c[3 * k + i] = u[BR_X1 + i] + 0.5 * delta * d1[i];
    }
    double f[BR_NDIM];
    if (braid_rhs(u, &m, f, NULL, NULL) != 0 || braid_contact_pressure(u, f, &m, &bp->p1[k], &bp->p2[k]) != 0)
      return CABLE_ERR_NONFINITE;
  }
  return CABLE_SUCCESS;
}

/* A knot's strands are two open tubes that join end to end (L + L2 = Ltot); a link's are closed. */
static int solution_is_knot(const cable_solution *s)
{
  return s->par[BP_LTOT] > 0 && fabs(s->par[BP_L] + s->par[BP_L2] - s->par[BP_LTOT]) < 1e-6 * s->par[BP_LTOT];
}

static int braid_solution_check(const cable_solution *s)
{
  return s && s->ndim == BR_NDIM && s->npar > BP_LTOT && s->u && cable_solution_npts(s) >= 2;
}

int cable_solution_strands(const cable_solution *s, cable_strands *out)
{
  if (!out) return CABLE_ERR_NULL;
  memset(out, 0, sizeof *out);
  if (!s) return CABLE_ERR_NULL;
  if (!braid_solution_check(s)) return CABLE_ERR_INPUT;
  braid_picture bp;
  int rc = picture_build(s, &bp);
  free(bp.c);
  *out = (cable_strands){bp.n, !solution_is_knot(s), 0.5 * s->par[BP_DELTA], bp.r1, bp.r2, bp.p1, bp.p2};
  if (rc) cable_strands_free(out);
  return rc;
}

void cable_strands_free(cable_strands *st)
{
  if (!st) return;
  free(st->r1); free(st->r2); free(st->p1); free(st->p2);
  memset(st, 0, sizeof *st);
}

/* The largest contact pressure is drawn this many drawn tube radii from the
 * contact curve: inside a strand's far edge (2 radii), so the profile stays
 * on the knot. */
#define RENDER_PROFILE_REACH 1.7

/* The PNG's caption: what the picture shows, in one line. */
static void picture_caption(const cable_solution *s, const cable_render_options *o, double pmax, char *buf, size_t n)
{
  cable_braid_analysis *a = malloc(sizeof *a);
  char topo[160] = "";
  if (a && cable_braid_analysis_compute(s, a) == 0)
    snprintf(topo, sizeof topo, ", Lk = %.4g, braid axis: %s, tubes %s", a->topo.lk, a->topo.axis.name,
             a->tube.noverlap > 0 ? "overlap" : "do not overlap");
  free(a);
  snprintf(buf, n,
           "cable render: label %d, T = %.8g, F = %.8g, Delta = %.6g%s; strand 1 red, strand 2 blue%s; "
           "contact pressure (max |p| = %.6g) along the contact curve: white on strand 1, black on strand 2, "
           "dark red where negative",
           s->lab, s->par[BP_T], s->par[BP_F], s->par[BP_DELTA], topo,
           o && o->colormap != CABLE_RENDER_COLORMAP_NONE ? " (coloured by contact pressure)" : "", pmax);
}

int cable_render_solution(const cable_solution *s, const cable_render_options *o, const char *out, const char *vtp,
                          const char *ply, cable_error *err)
{
  static const char *const png[1] = {".png"}, *const vtk[1] = {".vtp"}, *const plyx[1] = {".ply"};
  cable_error local;
  if (!err) err = &local;   /* the function reads err->status below */
  if (!s) return cable_error_set(err, CABLE_ERR_NULL, NULL, 0, "", "no solution (NULL)");
  if ((out && check_suffix(out, "o", png, 1, err)) || (vtp && check_suffix(vtp, "vtp", vtk, 1, err)) ||
      (ply && check_suffix(ply, "ply", plyx, 1, err)))
    return err->status;
  if (s->ndim != BR_NDIM || s->npar <= BP_LTOT)
    return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, "", "label %d is not a braid solution (NDIM=%d)", s->lab,
                           s->ndim);
  braid_picture bp;
  int rc = picture_build(s, &bp);
  if (rc) {
    picture_free(&bp);
    return cable_error_set(err, rc, NULL, 0, "", "cannot evaluate label %d: %s", s->lab, cable_status_message(rc));
  }
  int knot = solution_is_knot(s);
  double radius = 0.5 * s->par[BP_DELTA];
  /* strand 1 red, strand 2 blue */
  render_tube t[2] = {{bp.n, bp.r1, bp.p1, radius, {0.80, 0.20, 0.15}, !knot},
                      {bp.n, bp.r2, bp.p2, radius, {0.15, 0.35, 0.80}, !knot}};
  double pmax = 0;
  for (int k = 0; k < bp.n; k++) pmax = fmax(pmax, fmax(fabs(bp.p1[k]), fabs(bp.p2[k])));
  /* pressure profiles: white for strand 1, black for strand 2 (the paper's
     convention), dark red where the pressure is negative, each drawn from
     the contact curve towards the strand it acts on; the largest pressure
     reaches RENDER_PROFILE_REACH drawn tube radii, so that the profiles lie
     on the tubes (a strand's far edge is two radii from the contact curve)
     and read as a graph across them, whatever the picture's size */
  render_camera cam;
  double scale = 0;
  if (out && (rc = render_camera_fit(t, 2, o, &cam)) != CABLE_SUCCESS) {
    picture_free(&bp);
    return cable_error_set(err, rc, out, 0, "o", "cannot draw label %d: %s", s->lab, cable_status_message(rc));
  }
  if (out && pmax > 0) scale = RENDER_PROFILE_REACH * radius * cam.thicken / pmax;
  render_profile prof[2] = {{bp.c, bp.p1, bp.n, {1, 1, 1}, {0.6, 0, 0}, scale, bp.r1},
                            {bp.c, bp.p2, bp.n, {0, 0, 0}, {0.6, 0, 0}, scale, bp.r2}};
  if (out) {
    char caption[600];
    picture_caption(s, o, pmax, caption, sizeof caption);
    render_text text = {caption, "contact pressure"};
    rc = render_tubes_png_text(t, 2, prof, 2, o, &text, out);
    if (rc) cable_error_set(err, rc, out, 0, "o", "cannot write the picture: %s", cable_status_message(rc));
  }
  export_options eo = {0, "pressure"};
  if (!rc && vtp) {
    rc = export_vtp_write(t, 2, prof, 1, &eo, vtp);
    if (rc) cable_error_set(err, rc, vtp, 0, "vtp", "cannot write: %s", cable_status_message(rc));
  }
  if (!rc && ply) {
    rc = export_ply_write(t, 2, &eo, ply);
    if (rc) cable_error_set(err, rc, ply, 0, "ply", "cannot write: %s", cable_status_message(rc));
  }
  picture_free(&bp);
  return rc;
}

void cable_pictures_cleanup(void) { graphics_text_cleanup(); }
