/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The source folders of the layers, lowest first (doc/api.md, Layers; the
 * Makefile's LAYERS): test_layers.c checks their #include lines,
 * test_file_circles.c their calls.  continuation/base is the ground floor;
 * auto_iface/cli is the command line, a program over the library; the Python
 * extension (auto_iface/python) sees the public headers only and is checked
 * apart. */
#ifndef CABLE_TEST_LAYER_DIRS_H
#define CABLE_TEST_LAYER_DIRS_H

#include <string.h>

static const char *const layer_dirs[] = {"continuation/base", "continuation",      "equations",
                                         "bc",                "graphics",          "auto_iface/files",
                                         "auto_iface/autoeq", "auto_iface/session", "auto_iface/cli"};
#define NLAYER_DIRS ((int)(sizeof layer_dirs / sizeof layer_dirs[0]))

/* the index of a folder in layer_dirs, -1 if it is none of them */
static inline int layer_index(const char *dir)
{
  for (int k = 0; k < NLAYER_DIRS; k++)
    if (strcmp(layer_dirs[k], dir) == 0) return k;
  return -1;
}

#endif
