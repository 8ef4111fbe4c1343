/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The `cable` subcommands (auto_iface/cli/cable_main.c dispatches to these).
 * Each returns 0 or a negative cable_status with err filled. */
#ifndef CABLE_COMMANDS_H
#define CABLE_COMMANDS_H

#include <stdio.h>

#include "cable/cable_error.h"

/* cable run KEY=VALUE ...: one run(...) of a session in the current directory.
 * interrupt (NULL: none) is asked after every point, as the session's. */
int cable_cmd_run(int argc, char **argv, int (*interrupt)(void *ctx), void *ctx, cable_error *err);
/* cable info e=PROBLEM (a session in the current directory) */
int cable_cmd_info(const char *e, FILE *out, cable_error *err);
/* cable table b.NAME */
int cable_cmd_table(const char *bfile, FILE *out, cable_error *err);
/* cable list s.NAME (error estimates from d.NAME when present) */
int cable_cmd_list(const char *sfile, FILE *out, cable_error *err);
/* cable analyze s.NAME LABEL... [STAB=1] (the argument STAB=1: the Morse index too) */
int cable_cmd_analyze(const char *sfile, int nlab, char **labels, FILE *out, cable_error *err);

/* cable plot [x=COL] [y=COL] [o=FILE.png|FILE.svg] [title=TEXT] b.NAME ... */
int cable_cmd_plot(int argc, char **argv, cable_error *err);
/* cable render s.NAME LABEL [o=FILE.png] [view=X,Y,Z] [size=N] [thicken=K]
 *              [color=pressure] [vtp=FILE.vtp] [ply=FILE.ply] */
int cable_cmd_render(int argc, char **argv, cable_error *err);

#endif
