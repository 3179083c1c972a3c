/*
 * colors.c — OpenSCAD 2021.01's render colour schemes, as a table.
 *
 * Cornfield is compiled into OpenSCAD (src/colormap.cc,
 * RenderColorScheme::RenderColorScheme); the others are the JSON files it
 * installs under color-schemes/render/ (metallic.json, sunset.json, …).  We
 * take "background", "opencsg-face-front" and "opencsg-face-back", the three
 * colours its preview (OpenCSG) draws with.  The '#' and '%' modifier colours
 * are not part of any scheme: src/renderer.cc, Renderer::Renderer() sets
 * HIGHLIGHT = {255, 81, 81, 128} and BACKGROUND = {180, 180, 180, 128} (out
 * of 255) for every scheme.  Every value is sRGB, byte / 255.
 */
#include "render.h"

#include <string.h>
#include <strings.h>

typedef struct scheme {
    const char *name;
    unsigned background, face, back; /* 0xRRGGBB */
} scheme;

static const scheme schemes[] = {
    {"Cornfield", 0xffffe5, 0xf9d72c, 0x9dcb51},  {"Metallic", 0xaaaaff, 0xddddff, 0xdd22dd},
    {"Sunset", 0xaa4444, 0xffaaaa, 0x882233},     {"Starnight", 0x000000, 0xffffe0, 0x00ffff},
    {"BeforeDawn", 0x333333, 0xcccccc, 0x5563dd}, {"Nature", 0xfafafa, 0x16a085, 0xdbf4da},
    {"DeepOcean", 0x333333, 0xeeeeee, 0x0babc8},  {"Solarized", 0xfdf6e3, 0xb58800, 0x882233},
    {"Tomorrow", 0xf8f8f8, 0x4271ae, 0xf5871f},   {"Tomorrow Night", 0x1d1f21, 0x81a2be, 0xde935f},
    {"Monotone", 0xffffe5, 0xf9d72c, 0xf9d72c},
};

static void unpack(unsigned rgb, float out[3])
{
    out[0] = (float)((rgb >> 16) & 0xff) / 255.0f;
    out[1] = (float)((rgb >> 8) & 0xff) / 255.0f;
    out[2] = (float)(rgb & 0xff) / 255.0f;
}

const char *render_colors_name(int i)
{
    return i >= 0 && (size_t)i < sizeof schemes / sizeof schemes[0] ? schemes[i].name : NULL;
}

int render_colors_by_name(const char *name, render_colors *out)
{
    if (!name) return -1;
    const scheme *found = NULL;
    for (size_t i = 0; i < sizeof schemes / sizeof schemes[0] && !found; i++)
        if (strcmp(schemes[i].name, name) == 0) found = &schemes[i];
    /* OpenSCAD looks names up exactly; a different case is still unambiguous. */
    for (size_t i = 0; i < sizeof schemes / sizeof schemes[0] && !found; i++)
        if (strcasecmp(schemes[i].name, name) == 0) found = &schemes[i];
    if (!found) return -1;
    unpack(found->background, out->background);
    unpack(found->face, out->face);
    unpack(found->back, out->back);
    const float highlight[4] = {255, 81, 81, 128}, background[4] = {180, 180, 180, 128};
    for (int i = 0; i < 4; i++) {
        out->highlight[i] = highlight[i] / 255.0f;
        out->background_modifier[i] = background[i] / 255.0f;
    }
    return 0;
}
