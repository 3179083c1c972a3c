/*
 * versions.cpp — see versions.h.  Run-time versions where the library has
 * a call for it (the one actually loaded), else the headers' (OpenMesh has
 * no call).
 */
#include "versions.h"

#include <OpenMesh/Core/System/config.h>
#include <fontconfig/fontconfig.h>
#include <ft2build.h>
#include FT_FREETYPE_H
#include <hb.h>
#include <Model/COM/NMR_DLLInterfaces.h>
#include <cairo.h>

#include <cstdio>

extern "C" const char *io_openmesh_version(void)
{
    static char v[32];
    std::snprintf(v, sizeof v, "%d.%d", (OM_VERSION >> 16) & 0xff, (OM_VERSION >> 8) & 0xff);
    return v;
}

extern "C" const char *io_lib3mf_version(void)
{
    static char v[32];
    DWORD major = 0, minor = 0, micro = 0;
    if (NMR::lib3mf_getinterfaceversion(&major, &minor, &micro) != LIB3MF_OK) return "unknown";
    std::snprintf(v, sizeof v, "%u.%u.%u", (unsigned)major, (unsigned)minor, (unsigned)micro);
    return v;
}

extern "C" const char *io_freetype_version(void)
{
    static char v[32];
    FT_Library lib;
    if (FT_Init_FreeType(&lib) != 0) return "unknown";
    FT_Int a, b, c;
    FT_Library_Version(lib, &a, &b, &c);
    FT_Done_FreeType(lib);
    std::snprintf(v, sizeof v, "%d.%d.%d", a, b, c);
    return v;
}

extern "C" const char *io_harfbuzz_version(void)
{
    return hb_version_string();
}

extern "C" const char *io_fontconfig_version(void)
{
    static char v[32];
    int n = FcGetVersion();
    std::snprintf(v, sizeof v, "%d.%d.%d", n / 10000, n / 100 % 100, n % 100);
    return v;
}

extern "C" const char *io_cairo_version(void)
{
    return cairo_version_string();
}

extern "C" int io_font_count(void)
{
    /* A configuration of its own, destroyed after: the default one would
     * live to the end of the process (a leak to LeakSanitizer). */
    FcConfig *config = FcInitLoadConfigAndFonts();
    if (!config) return -1;
    FcPattern *pat = FcPatternCreate();
    FcObjectSet *os = FcObjectSetBuild(FC_FILE, (char *)nullptr);
    FcFontSet *fs = pat && os ? FcFontList(config, pat, os) : nullptr;
    int n = fs ? fs->nfont : -1;
    if (fs) FcFontSetDestroy(fs);
    if (os) FcObjectSetDestroy(os);
    if (pat) FcPatternDestroy(pat);
    FcConfigDestroy(config);
    return n;
}
