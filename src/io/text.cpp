/*
 * text.cpp — io_text_render (text.h): fontconfig finds the font, HarfBuzz
 * shapes the string, FreeType gives each glyph's outline, and the outline's
 * Bézier curves become `segments` chords each — the layout of OpenSCAD
 * 2021.01's FreetypeRenderer, number for number:
 *
 *   - the face is set to char size size·1000 (26.6 points) at 100 dpi, and
 *     outline coordinates (26.6 pixels) are divided by 1000, so an em is
 *     size·100/72 model units;
 *   - HarfBuzz advances and offsets, and the glyph boxes used to align,
 *     are divided by 64·16 = 1024 instead (OpenSCAD's own inconsistency,
 *     kept so that the text lands where OpenSCAD puts it);
 *   - halign/valign shift by the advance width and the largest ascent and
 *     descent of the grid-fitted glyph boxes;
 *   - script and direction, when not given, are detected from the text's
 *     code points as OpenSCAD's detect_properties does.
 *
 * Each glyph is filled by the even-odd rule (TrueType holes), then the
 * glyphs are united (polygon.h).  Not done: OpenSCAD's remapping of
 * Windows symbol fonts to the 0xf000 page.  No exception crosses the C
 * boundary and nothing prints.
 */
#include "text.h"

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_GLYPH_H
#include FT_OUTLINE_H

#include <fontconfig/fontconfig.h>
#include <hb-ft.h>
#include <hb.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>
#include <set>
#include <string>
#include <vector>

namespace
{

const double SCALE = 1000;         /* FreetypeRenderer::scale */
const double HB_SCALE = 64.0 * 16; /* its divisor for advances and boxes */

void set_err(char *err, size_t errlen, const std::string &msg)
{
    if (err && errlen) std::snprintf(err, errlen, "%s", msg.c_str());
}

struct Pt {
    double x, y;
};

/* The outlines of one glyph being drawn (OpenSCAD's DrawingCallback). */
struct Drawing {
    unsigned long fn;
    double per; /* FreeType units per model unit: SCALE, over the size's reduction */
    Pt pen{0, 0}, offset{0, 0}, advance{0, 0};
    std::vector<std::vector<Pt>> contours;

    void add(Pt v)
    {
        contours.back().push_back({v.x + offset.x + advance.x, v.y + offset.y + advance.y});
    }
};

Pt scaled(const Drawing *d, const FT_Vector *v)
{
    return {v->x / d->per, v->y / d->per};
}

int move_to(const FT_Vector *to, void *user)
{
    Drawing *d = static_cast<Drawing *>(user);
    d->contours.emplace_back();
    d->pen = scaled(d, to);
    d->add(d->pen);
    return 0;
}

int line_to(const FT_Vector *to, void *user)
{
    Drawing *d = static_cast<Drawing *>(user);
    if (d->contours.empty()) d->contours.emplace_back();
    d->pen = scaled(d, to);
    d->add(d->pen);
    return 0;
}

int conic_to(const FT_Vector *c, const FT_Vector *to, void *user)
{
    Drawing *d = static_cast<Drawing *>(user);
    if (d->contours.empty()) d->contours.emplace_back();
    Pt p0 = d->pen, p1 = scaled(d, c), p2 = scaled(d, to);
    for (unsigned long i = 1; i <= d->fn; i++) {
        double a = i * (1.0 / (double)d->fn), b = 1 - a;
        d->add({p0.x * b * b + p1.x * 2 * b * a + p2.x * a * a,
                p0.y * b * b + p1.y * 2 * b * a + p2.y * a * a});
    }
    d->pen = p2;
    return 0;
}

int cubic_to(const FT_Vector *c1, const FT_Vector *c2, const FT_Vector *to, void *user)
{
    Drawing *d = static_cast<Drawing *>(user);
    if (d->contours.empty()) d->contours.emplace_back();
    Pt p0 = d->pen, p1 = scaled(d, c1), p2 = scaled(d, c2), p3 = scaled(d, to);
    for (unsigned long i = 1; i <= d->fn; i++) {
        double a = i * (1.0 / (double)d->fn), b = 1 - a;
        d->add({p0.x * b * b * b + p1.x * 3 * b * b * a + p2.x * 3 * b * a * a + p3.x * a * a * a,
                p0.y * b * b * b + p1.y * 3 * b * b * a + p2.y * 3 * b * a * a + p3.y * a * a * a});
    }
    d->pen = p3;
    return 0;
}

/* The font file and face index fontconfig picks for pattern name, as
 * OpenSCAD's FontCache (config substitution, default substitution,
 * best match). */
FcConfig *config = nullptr;

/* fontconfig keeps its configuration and caches until FcFini: let them go
 * at exit, so that leak checkers (LeakSanitizer, valgrind) see a clean
 * process. */
void release_fonts()
{
    if (config) FcConfigDestroy(config);
    config = nullptr;
    FcFini();
}

/* The font files added to the configuration (FontCache::register_font_file). */
std::set<std::string> added_fonts;

bool find_font(const char *name, const io_text_params *p, std::string &file, int &index)
{
    if (!config) {
        config = FcInitLoadConfigAndFonts();
        if (config) std::atexit(release_fonts);
    }
    if (!config) return false;
    for (int i = 0; i < p->nfont_files; i++) {
        const char *f = p->font_files[i];
        if (added_fonts.count(f)) continue;
        added_fonts.insert(f);
        FcConfigAppFontAddFile(config, reinterpret_cast<const FcChar8 *>(f));
    }
    FcPattern *pat = FcNameParse(reinterpret_cast<const FcChar8 *>(name));
    if (!pat) return false;
    FcConfigSubstitute(config, pat, FcMatchPattern);
    FcDefaultSubstitute(pat);
    FcResult result;
    FcPattern *match = FcFontMatch(config, pat, &result);
    FcPatternDestroy(pat);
    if (!match) return false;
    FcChar8 *f = nullptr;
    bool ok = FcPatternGetString(match, FC_FILE, 0, &f) == FcResultMatch && f;
    if (ok) {
        file = reinterpret_cast<const char *>(f);
        if (FcPatternGetInteger(match, FC_INDEX, 0, &index) != FcResultMatch) index = 0;
    }
    FcPatternDestroy(match);
    return ok;
}

bool ignored_script(hb_script_t s)
{
    return s == HB_SCRIPT_COMMON || s == HB_SCRIPT_INHERITED || s == HB_SCRIPT_UNKNOWN ||
           s == HB_SCRIPT_INVALID;
}

/* OpenSCAD's detect_properties: the script of the text's code points (one
 * script, or unknown when they mix), and the direction of that script. */
void detect(const std::string &text, std::string &script, std::string &direction)
{
    if (hb_direction_from_string(direction.c_str(), -1) != HB_DIRECTION_INVALID &&
        hb_script_from_string(script.c_str(), -1) != HB_SCRIPT_INVALID)
        return;
    hb_script_t sc = hb_script_from_string(script.c_str(), -1);
    if (sc == HB_SCRIPT_INVALID) {
        hb_buffer_t *buf = hb_buffer_create();
        hb_buffer_add_utf8(buf, text.c_str(), (int)text.size(), 0, (int)text.size());
        unsigned int n = 0;
        hb_glyph_info_t *info = hb_buffer_get_glyph_infos(buf, &n);
        for (unsigned int i = 0; i < n; i++) {
            hb_script_t s = hb_unicode_script(hb_unicode_funcs_get_default(), info[i].codepoint);
            if (ignored_script(s)) continue;
            if (sc == HB_SCRIPT_INVALID)
                sc = s;
            else if (sc != s && sc != HB_SCRIPT_UNKNOWN)
                sc = HB_SCRIPT_UNKNOWN;
        }
        hb_buffer_destroy(buf);
        if (!ignored_script(sc)) {
            char tag[5] = {0};
            hb_tag_to_string(hb_script_to_iso15924_tag(sc), tag);
            script = tag;
        }
    }
    if (hb_direction_from_string(direction.c_str(), -1) == HB_DIRECTION_INVALID) {
        hb_direction_t d = hb_script_get_horizontal_direction(sc);
        direction = d == HB_DIRECTION_INVALID ? "" : hb_direction_to_string(d);
    }
}

struct Glyph {
    FT_Glyph glyph;
    hb_glyph_position_t pos;
};

int render(const io_text_params *p, io_paths *out, char *err, size_t errlen)
{
    out->pts = nullptr;
    out->start = nullptr;
    out->npaths = 0;
    std::string text = p->text ? p->text : "";
    std::string font = p->font && *p->font ? p->font : "Liberation Sans:style=Regular";
    std::string script = p->script ? p->script : "";
    std::string direction = p->direction ? p->direction : "";
    std::string language = p->language && *p->language ? p->language : "en";
    std::string halign = p->halign && *p->halign ? p->halign : "left";
    std::string valign = p->valign && *p->valign ? p->valign : "baseline";
    if (text.empty()) return 0;
    detect(text, script, direction);

    std::string file;
    int index = 0;
    if (!find_font(font.c_str(), p, file, index)) {
        set_err(err, errlen, "no font found for '" + font + "'");
        return 1;
    }
    FT_Library lib;
    if (FT_Init_FreeType(&lib)) {
        set_err(err, errlen, "cannot initialise FreeType");
        return -1;
    }
    if (p->font_used && p->font_used_len)
        std::snprintf(p->font_used, p->font_used_len, "%s", file.c_str());
    FT_Face face;
    if (FT_New_Face(lib, file.c_str(), index, &face)) {
        FT_Done_FreeType(lib);
        set_err(err, errlen, "cannot open font file " + file);
        return 1;
    }
    /* Unicode, else a Windows symbol charmap (platform 3, encoding 0), as
     * 2021.01's FontCache::init_face: a symbol font such as MarVoSym has
     * no other, and harfbuzz finds its glyphs at U+F000 + code too */
    if (FT_Select_Charmap(face, FT_ENCODING_UNICODE))
        for (int i = 0; i < face->num_charmaps; i++)
            if (face->charmaps[i]->platform_id == 3 && face->charmaps[i]->encoding_id == 0) {
                FT_Set_Charmap(face, face->charmaps[i]);
                break;
            }
    int rc = 0;
    std::vector<Glyph> glyphs;
    hb_font_t *hbf = nullptr;
    hb_buffer_t *buf = nullptr;
    std::vector<double> pts;
    std::vector<int> starts;
    try {
        /* A size whose 26.6 value is no long is one FreeType cannot take
         * either (converting it would be undefined). */
        double size = p->size * SCALE;
        /* FreeType takes at most 65535 pixels per em (about size 3000
         * here) and loads no glyph near that, where 2021.01 draws any
         * size: a size over 2048 is set halved until it is below, and its
         * outlines, advances and boxes (linear in the size) are doubled
         * back, k times */
        double k = 1;
        while (std::fabs(size / k) > 2048 * SCALE && k < 0x1p60)
            k *= 2;
        int set = std::fabs(size) < 0x1p62
                      ? FT_Set_Char_Size(face, 0, (FT_F26Dot6)(size / k), 100, 100)
                      : 1;
        if (set) {
            set_err(err, errlen, "cannot set font size for font " + font);
            throw 2; /* OpenSCAD 2021.01 draws nothing and goes on */
        }
        const double hb_scale = HB_SCALE / k;
        hbf = hb_ft_font_create(face, nullptr);
        buf = hb_buffer_create();
        hb_buffer_set_direction(buf, hb_direction_from_string(direction.c_str(), -1));
        hb_buffer_set_script(buf, hb_script_from_string(script.c_str(), -1));
        hb_buffer_set_language(buf, hb_language_from_string(language.c_str(), -1));
        hb_buffer_add_utf8(buf, text.c_str(), (int)text.size(), 0, (int)text.size());
        hb_buffer_guess_segment_properties(buf); /* only fills what is unset */
        hb_shape(hbf, buf, nullptr, 0);
        unsigned int n = 0;
        hb_glyph_info_t *info = hb_buffer_get_glyph_infos(buf, &n);
        hb_glyph_position_t *pos = hb_buffer_get_glyph_positions(buf, &n);
        for (unsigned int i = 0; i < n; i++) {
            if (FT_Load_Glyph(face, info[i].codepoint, FT_LOAD_DEFAULT)) continue;
            FT_Glyph g;
            if (FT_Get_Glyph(face->glyph, &g)) continue;
            glyphs.push_back({g, pos[i]});
        }
        bool horizontal = HB_DIRECTION_IS_HORIZONTAL(hb_buffer_get_direction(buf));
        double width = 0, ascend = 0, descend = 0;
        for (const Glyph &g : glyphs) {
            FT_BBox box;
            FT_Glyph_Get_CBox(g.glyph, FT_GLYPH_BBOX_GRIDFIT, &box);
            if (horizontal) {
                width += g.pos.x_advance / hb_scale * p->spacing;
                ascend = std::max(ascend, std::max(0.0, box.yMax / hb_scale));
                descend = std::max(descend, std::max(0.0, -box.yMin / hb_scale));
            } else {
                width = std::max(width, (box.xMax - box.xMin) / hb_scale);
                ascend += g.pos.y_advance / hb_scale * p->spacing;
            }
        }
        double xo = halign == "right" ? -width : halign == "center" ? -width / 2 : 0;
        double yo = valign == "top"      ? -ascend
                    : valign == "center" ? descend / 2 - ascend / 2
                    : valign == "bottom" ? descend
                                         : 0;
        FT_Outline_Funcs funcs;
        funcs.move_to = move_to;
        funcs.line_to = line_to;
        funcs.conic_to = conic_to;
        funcs.cubic_to = cubic_to;
        funcs.shift = 0;
        funcs.delta = 0;
        Drawing d;
        d.fn = (unsigned long)std::max(p->segments, 1);
        d.per = SCALE / k;
        for (const Glyph &g : glyphs) {
            d.contours.clear();
            d.offset = {xo + g.pos.x_offset / hb_scale, yo + g.pos.y_offset / hb_scale};
            if (g.glyph->format == FT_GLYPH_FORMAT_OUTLINE) {
                FT_Outline outline = reinterpret_cast<FT_OutlineGlyph>(g.glyph)->outline;
                FT_Outline_Decompose(&outline, &funcs, &d);
            }
            d.advance.x += g.pos.x_advance / hb_scale * p->spacing;
            d.advance.y += g.pos.y_advance / hb_scale * p->spacing;
            /* one glyph, even-odd, normalised */
            std::vector<double> gp;
            std::vector<int> gs;
            for (const auto &c : d.contours) {
                if (c.size() < 3) continue;
                gs.push_back((int)(gp.size() / 2));
                for (const Pt &q : c) {
                    gp.push_back(q.x);
                    gp.push_back(q.y);
                }
            }
            if (gs.empty()) continue;
            gs.push_back((int)(gp.size() / 2));
            io_paths in = {reinterpret_cast<double(*)[2]>(gp.data()), gs.data(),
                           (int)gs.size() - 1};
            io_paths norm;
            if (io_polygon_clip(IO_CLIP_UNION, &in, 1, nullptr, 0, &norm, err, errlen) != 0)
                throw 1;
            for (int i = 0; i < norm.npaths; i++) {
                starts.push_back((int)(pts.size() / 2));
                for (int k = norm.start[i]; k < norm.start[i + 1]; k++) {
                    pts.push_back(norm.pts[k][0]);
                    pts.push_back(norm.pts[k][1]);
                }
            }
            io_paths_free(&norm);
        }
        if (!starts.empty()) {
            starts.push_back((int)(pts.size() / 2));
            io_paths all = {reinterpret_cast<double(*)[2]>(pts.data()), starts.data(),
                            (int)starts.size() - 1};
            if (io_polygon_clip(IO_CLIP_UNION, &all, 0, nullptr, 0, out, err, errlen) != 0) throw 1;
        }
    } catch (int why) {
        rc = why == 2 ? 1 : -1;
    }
    for (Glyph &g : glyphs)
        FT_Done_Glyph(g.glyph);
    if (buf) hb_buffer_destroy(buf);
    if (hbf) hb_font_destroy(hbf);
    FT_Done_Face(face);
    FT_Done_FreeType(lib);
    return rc;
}

} // namespace

extern "C" int io_text_render(const io_text_params *p, io_paths *out, char *err, size_t errlen)
{
    try {
        return render(p, out, err, errlen);
    } catch (const std::bad_alloc &) {
        set_err(err, errlen, "out of memory");
    } catch (...) {
        set_err(err, errlen, "text rendering failed");
    }
    return -1;
}
