/*
 * viewer_text.c — see viewer_text.h.
 */
#include "viewer_text.h"

#include <SDL_ttf.h>
#include <fontconfig/fontconfig.h>
#include <stdlib.h>
#include <string.h>

struct viewer_text {
    TTF_Font *font;
};

/* The file of fontconfig's best match for "sans-serif" (malloc'ed), or NULL. */
static char *sans_file(void)
{
    FcConfig *cfg = FcInitLoadConfigAndFonts();
    if (!cfg) return NULL;
    char *file = NULL;
    FcPattern *pat = FcNameParse((const FcChar8 *)"sans-serif");
    if (pat && FcConfigSubstitute(cfg, pat, FcMatchPattern)) {
        FcDefaultSubstitute(pat);
        FcResult res;
        FcPattern *match = FcFontMatch(cfg, pat, &res);
        FcChar8 *f;
        if (match && FcPatternGetString(match, FC_FILE, 0, &f) == FcResultMatch)
            file = strdup((const char *)f);
        if (match) FcPatternDestroy(match);
    }
    if (pat) FcPatternDestroy(pat);
    FcConfigDestroy(cfg);
    return file;
}

viewer_text *viewer_text_new(int px)
{
    if (TTF_Init() != 0) return NULL;
    char *file = sans_file();
    TTF_Font *font = file ? TTF_OpenFont(file, px) : NULL;
    free(file);
    viewer_text *t = font ? malloc(sizeof *t) : NULL;
    if (!t) {
        if (font) TTF_CloseFont(font);
        TTF_Quit();
        return NULL;
    }
    t->font = font;
    return t;
}

void viewer_text_free(viewer_text *t)
{
    if (!t) return;
    TTF_CloseFont(t->font);
    free(t);
    TTF_Quit();
}

void viewer_text_draw(viewer_text *t, SDL_Renderer *ren, const char *text, int x, int y, int bottom,
                      int max_w, SDL_Color fg, SDL_Color bg)
{
    if (!t || !text[0] || max_w < 16) return;
    int pad = 6;
    SDL_Surface *s = TTF_RenderUTF8_Blended_Wrapped(t->font, text, fg, (Uint32)(max_w - 2 * pad));
    if (!s) return;
    SDL_Texture *tex = SDL_CreateTextureFromSurface(ren, s);
    if (tex) {
        SDL_Rect box = {x, bottom ? y - s->h - 2 * pad : y, s->w + 2 * pad, s->h + 2 * pad};
        SDL_SetRenderDrawBlendMode(ren, SDL_BLENDMODE_BLEND);
        SDL_SetRenderDrawColor(ren, bg.r, bg.g, bg.b, bg.a);
        SDL_RenderFillRect(ren, &box);
        SDL_Rect dst = {box.x + pad, box.y + pad, s->w, s->h};
        SDL_RenderCopy(ren, tex, NULL, &dst);
        SDL_DestroyTexture(tex);
    }
    SDL_FreeSurface(s);
}
