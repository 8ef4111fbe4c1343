/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Text placement for cairo. */
#include "graphics_text.h"

#include <dlfcn.h>
#include <string.h>

void graphics_text_font(cairo_t *cr, double size, int bold)
{
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
}

void graphics_text_show(cairo_t *cr, double x, double y, const char *s, double ax, double ay)
{
  cairo_text_extents_t e;
  cairo_text_extents(cr, s, &e);
  cairo_move_to(cr, x - e.x_bearing - ax * e.width, y - e.y_bearing - ay * e.height);
  cairo_show_text(cr, s);
  cairo_new_path(cr);
}

double graphics_text_width(cairo_t *cr, const char *s)
{
  cairo_text_extents_t e;
  cairo_text_extents(cr, s, &e);
  return e.x_advance;
}

void graphics_text_cleanup(void)
{
  cairo_debug_reset_static_data();
  /* fontconfig is loaded as cairo's dependency; cable does not link it
   * directly, so its FcFini is looked up at run time */
  void *lib = dlopen("libfontconfig.so.1", RTLD_LAZY);
  if (lib == NULL) return;
  void *sym = dlsym(lib, "FcFini");
  if (sym != NULL) {
    void (*fini)(void);
    memcpy(&fini, &sym, sizeof fini);
    fini();
  }
  dlclose(lib);
}
