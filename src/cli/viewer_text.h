/*
 * viewer_text.h — text in the viewer's window (SDL2_ttf, the system's sans
 * font found through fontconfig): the keys on `?`, a failed load's error.
 */
#ifndef RAYSCAD_CLI_VIEWER_TEXT_H
#define RAYSCAD_CLI_VIEWER_TEXT_H

#include <SDL.h>

typedef struct viewer_text viewer_text;

/* Text of about `px` pixels a line; NULL (nothing drawn then) when no font
 * can be found or opened. */
viewer_text *viewer_text_new(int px);
void viewer_text_free(viewer_text *t);

/* Draw text (lines split at '\n', each wrapped to the box) in a box of at
 * most max_w pixels wide, at (x, y) from the top left, or when bottom is 1
 * with its bottom edge at y: colour fg on a translucent bg. */
void viewer_text_draw(viewer_text *t, SDL_Renderer *ren, const char *text, int x, int y, int bottom,
                      int max_w, SDL_Color fg, SDL_Color bg);

#endif
