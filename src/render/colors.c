/*
 * colors.c — OpenSCAD 2021.01's render colour schemes, as a table.
 *
 * Cornfield is compiled into OpenSCAD (src/colormap.cc,
 * RenderColorScheme::RenderColorScheme); the others are the JSON files it
 * installs under color-schemes/render/ (metallic.json, sunset.json, …).  We
 * take "background", "opencsg-face-front" and "opencsg-face-back", the three
 * colours its preview (OpenCSG) draws with, and "axes-color" and
 * "crosshair" for the --view lines (Cornfield's: black and #800000).  The '#' and '%' modifier
 * colours are not part of any scheme: src/renderer.cc, Renderer::Renderer() sets HIGHLIGHT = {255,
 * 81, 81, 128} and BACKGROUND = {180, 180, 180, 128} (out of 255) for every scheme.  Every value is
 * sRGB, byte / 255.
 */
#include "render.h"

#include <string.h>
#include <strings.h>

typedef struct scheme {
    const char *name;
    unsigned background, face, back, axes, crosshair; /* 0xRRGGBB */
} scheme;

static const scheme schemes[] = {
    {"Cornfield", 0xffffe5, 0xf9d72c, 0x9dcb51, 0x000000, 0x800000},
    {"Metallic", 0xaaaaff, 0xddddff, 0xdd22dd, 0x222233, 0x800000},
    {"Sunset", 0xaa4444, 0xffaaaa, 0x882233, 0x220d0d, 0x800000},
    {"Starnight", 0x000000, 0xffffe0, 0x00ffff, 0xe5e5e5, 0xf0f0f0},
    {"BeforeDawn", 0x333333, 0xcccccc, 0x5563dd, 0xc1c1c1, 0xf0f0f0},
    {"Nature", 0xfafafa, 0x16a085, 0xdbf4da, 0x323232, 0x111111},
    {"DeepOcean", 0x333333, 0xeeeeee, 0x0babc8, 0xc1c1c1, 0xf0f0f0},
    {"Solarized", 0xfdf6e3, 0xb58800, 0x882233, 0x191816, 0x800000},
    {"Tomorrow", 0xf8f8f8, 0x4271ae, 0xf5871f, 0x181818, 0x8959a8},
    {"Tomorrow Night", 0x1d1f21, 0x81a2be, 0xde935f, 0xe8e8e8, 0xb294bb},
    {"Monotone", 0xffffe5, 0xf9d72c, 0xf9d72c, 0x191916, 0x800000},
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
    unpack(found->axes, out->axes);
    unpack(found->crosshair, out->crosshair);
    const float highlight[4] = {255, 81, 81, 128}, background[4] = {180, 180, 180, 128};
    for (int i = 0; i < 4; i++) {
        out->highlight[i] = highlight[i] / 255.0f;
        out->background_modifier[i] = background[i] / 255.0f;
    }
    return 0;
}
