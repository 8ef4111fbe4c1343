/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The picture commands of the command line, `cable plot` and `cable render`:
 * their options read into the calls of the public picture API
 * (cable/cable_pictures.h). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cable/cable_aufile.h"
#include "cable/cable_pictures.h"
#include "cable/cable_status.h"
#include "cable_commands.h"

/* KEY=VALUE option or NULL */
static const char *option(const char *arg, const char *key)
{
  size_t n = strlen(key);
  return strncmp(arg, key, n) == 0 && arg[n] == '=' ? arg + n + 1 : NULL;
}

int cable_cmd_plot(int argc, char **argv, cable_error *err)
{
  const char *xcol = NULL, *ycol = NULL, *out = "diagram.png", *title = NULL;
  const char *files[64];
  int nfiles = 0;
  for (int i = 0; i < argc; i++) {
    const char *v;
    if ((v = option(argv[i], "x"))) xcol = v;
    else if ((v = option(argv[i], "y"))) ycol = v;
    else if ((v = option(argv[i], "o"))) out = v;
    else if ((v = option(argv[i], "title"))) title = v;
    else if (strchr(argv[i], '='))
      return cable_error_set(err, CABLE_ERR_INPUT, "<command line>", 0, argv[i], "unknown option (x=, y=, o=, title=)");
    else if (nfiles >= 64)
      return cable_error_set(err, CABLE_ERR_INPUT, "<command line>", 0, argv[i], "at most 64 b-files");
    else files[nfiles++] = argv[i];
  }
  int rc = cable_plot_files(NULL, files, nfiles, xcol, ycol, NULL, 0, title, out, err);
  if (!rc) printf("cable: diagram written to %s\n", out);
  return rc;
}

int cable_cmd_render(int argc, char **argv, cable_error *err)
{
  if (argc < 2) return cable_error_set(err, CABLE_ERR_INPUT, "<command line>", 0, "", "usage: cable render s.NAME LABEL [options]");
  const char *out = "knot.png", *vtp = NULL, *ply = NULL;
  cable_render_options o;
  memset(&o, 0, sizeof o);
  int rc = 0;
  for (int i = 2; i < argc && !rc; i++) {
    const char *v;
    if ((v = option(argv[i], "o"))) out = v;
    else if ((v = option(argv[i], "vtp"))) vtp = v;
    else if ((v = option(argv[i], "ply"))) ply = v;
    else if ((v = option(argv[i], "size"))) o.width = o.height = atoi(v);
    else if ((v = option(argv[i], "thicken"))) o.thicken = atof(v);
    else if ((v = option(argv[i], "color"))) {
      if (strcmp(v, "pressure") == 0) o.colormap = CABLE_RENDER_COLORMAP_DIVERGING;
      else rc = cable_error_set(err, CABLE_ERR_INPUT, "<command line>", 0, argv[i], "color=pressure is the only colour map");
    } else if ((v = option(argv[i], "view"))) {
      if (sscanf(v, "%lf,%lf,%lf", &o.view_dir[0], &o.view_dir[1], &o.view_dir[2]) != 3)
        rc = cable_error_set(err, CABLE_ERR_INPUT, "<command line>", 0, argv[i], "view=X,Y,Z (three numbers)");
    } else
      rc = cable_error_set(err, CABLE_ERR_INPUT, "<command line>", 0, argv[i],
                           "unknown option (o=, size=, view=, thicken=, color=pressure, vtp=, ply=)");
  }
  if (rc) return rc;
  cable_sfile *sf = cable_sfile_read(argv[0], err);
  if (!sf) return err->status ? err->status : CABLE_ERR_IO;
  const cable_solution *s = cable_sfile_find(sf, argv[1], err);
  if (!s) rc = err->status ? err->status : CABLE_ERR_NOTFOUND;
  else rc = cable_render_solution(s, &o, out, vtp, ply, err);
  if (!rc) {
    printf("cable: label %d rendered to %s\n", s->lab, out);
    if (vtp) printf("cable: VTK PolyData written to %s\n", vtp);
    if (ply) printf("cable: PLY mesh written to %s\n", ply);
  }
  cable_sfile_free(sf);
  return rc;
}
