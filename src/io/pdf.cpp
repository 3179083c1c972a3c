/*
 * pdf.cpp — see pdf.h.  The page is openscad 2021.01's (its export_pdf.cc),
 * drawn with the same cairo operations in the same order, so that the two
 * files rasterise alike:
 *
 *   A4 portrait, 595 x 842 points; a millimetre is 2.8346 points, openscad's
 *   rounding of 72 / 25.4 = 2.834646 (kept: its printed scale is 0.0016 %
 *   short, and ours must be the same).
 *   Where the origin goes: when the bounds, rounded as openscad rounds them
 *   (min x and max y down, max x and min y up), are all >= 0, the model's
 *   origin sits 30 points in from the page's bottom-left corner and the
 *   rulers start at that corner (their tick "0" lies 10 mm in, 1.65 points
 *   short of the model's origin, as in openscad); otherwise the origin is
 *   the page's centre, and so is the rulers' 0.
 *   The outlines: each path a move to its first point, lines to the others
 *   and back to the first, not closed (the first corner gets butt ends, not
 *   a mitre, as openscad's), all stroked at once, opaque black, 1 point
 *   wide, nothing filled.
 *   The rulers: ticks 10 mm apart and 12 mm long, 0.4 points wide, black at
 *   40 % alpha, every other one labelled in 6-point type; along the bottom
 *   and the left edge of the page.  Centred, the two ticks at 0 are drawn
 *   again in opaque black.  Last, openscad's "Scale is to calibrate …" line
 *   in 5-point type.  The type is cairo's default face (fontconfig's
 *   sans-serif), as openscad leaves it.
 *
 * openscad also draws the source file's path in 10-point type; its command
 * line passes an empty path, so there is nothing to draw and we draw
 * nothing.  The metadata: an empty title as openscad's, no dates (the same
 * model gives the same bytes), and rayscad as the creator where openscad
 * names itself.
 *
 * The type: openscad draws with cairo's toy font API, whose default face
 * is fontconfig's match for the family "" at normal slant and weight.  A
 * toy face is matched through fontconfig's default configuration, which
 * then lives to the end of the process with the patterns cairo keeps (a
 * leak to LeakSanitizer: fontconfig's offset-encoded pointers hide them).
 * So the same match is made here through a configuration of our own,
 * destroyed at once, and the face handed to cairo as a FreeType face,
 * released when cairo lets it go; the glyphs, the embedded subset and the
 * page's bytes are the toy face's (tests/rayscad/test_region.c compares
 * them with openscad's).  The toy face stays the fallback when no font
 * matches.  Nothing here throws: no C++ library is used.
 */
#include "pdf.h"
#include "region_export.h"

#include "../../include/rayscad.h"

#include <cairo-ft.h>
#include <cairo-pdf.h>
#include <cairo.h>
#include <fontconfig/fontconfig.h>
#include <ft2build.h>
#include FT_FREETYPE_H

#include <cerrno>
#include <cmath>
#include <new>
#include <cstdio>
#include <cstring>

namespace
{

constexpr double page_w = 595.0, page_h = 842.0, margin = 30.0;

double points(double mm)
{
    return mm * 2.8346;
}

/* openscad's choice of origin: the bounding box's corners rounded as it
 * rounds them, all >= 0.  floor(min x) >= 0 is min x >= 0, ceil(min y) >= 0
 * is min y > -1; compared as doubles, so no int conversion can overflow. */
bool bottom_left(const double (*pts)[2], const int *start, int npaths)
{
    if (start[npaths] <= start[0]) return true;
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int k = start[0]; k < start[npaths]; k++)
        for (int a = 0; a < 2; a++) {
            lo[a] = std::fmin(lo[a], pts[k][a]);
            hi[a] = std::fmax(hi[a], pts[k][a]);
        }
    return std::floor(lo[0]) >= 0 && std::ceil(lo[1]) >= 0 && std::floor(hi[1]) >= 0 &&
           std::ceil(hi[0]) >= 0;
}

void outlines(cairo_t *cr, const double (*pts)[2], const int *start, int npaths)
{
    for (int i = 0; i < npaths; i++) {
        int k0 = start[i], n = start[i + 1] - k0;
        if (n <= 0) continue;
        cairo_move_to(cr, points(pts[k0][0]), points(-pts[k0][1]));
        for (int k = k0 + 1; k < k0 + n; k++)
            cairo_line_to(cr, points(pts[k][0]), points(-pts[k][1]));
        cairo_line_to(cr, points(pts[k0][0]), points(-pts[k0][1]));
    }
}

void line(cairo_t *cr, double x0, double y0, double x1, double y1)
{
    cairo_move_to(cr, x0, y0);
    cairo_line_to(cr, x1, y1);
    cairo_stroke(cr);
}

void label(cairo_t *cr, double x, double y, int value)
{
    char text[16];
    std::snprintf(text, sizeof text, "%d", value);
    cairo_move_to(cr, x, y);
    cairo_show_text(cr, text);
}

void text(cairo_t *cr, double x, double y, double size, const char *s)
{
    cairo_set_font_size(cr, size);
    cairo_move_to(cr, x, y);
    cairo_show_text(cr, s);
}

const char about[] = "Scale is to calibrate actual printed dimension. Check both X and Y. "
                     "Measure between tick 0 and last tick";

/* The rulers of the bottom-left layout, the origin at the page's corner:
 * 19 ticks along the bottom and 29 up the left edge, the first at 10 mm,
 * labelled 0, 20, 40 … (the tick's distance less 10 mm). */
void rulers_from_corner(cairo_t *cr)
{
    const double step = points(10), len = points(12), at = points(8);
    for (int i = 1; i < 20; i++) {
        line(cr, i * step, 0, i * step, -len);
        if (i % 2 == 1) label(cr, i * step + 1.5, -at, (i - 1) * 10);
    }
    for (int i = 1; i < 30; i++) {
        line(cr, 0, -i * step, len, -i * step);
        if (i % 2 == 1) label(cr, at, -i * step - 1.5, (i - 1) * 10);
    }
}

/* The rulers of the centred layout, the origin at the page's centre: ticks
 * at -90 … 90 mm along the bottom and -140 … 140 mm up the left edge,
 * labelled every 20 mm (the left ruler's labels count upwards), the two at
 * 0 drawn again in opaque black. */
void rulers_from_centre(cairo_t *cr)
{
    const double step = points(10), len = points(12), at = points(8);
    const double bottom = page_h / 2, left = -page_w / 2;
    for (int i = 0; i < 10; i++) {
        line(cr, i * step, bottom, i * step, bottom - len);
        if (i % 2 == 0) label(cr, i * step + 1.5, bottom - at, i * 10);
    }
    for (int i = 1; i < 10; i++) {
        line(cr, -i * step, bottom, -i * step, bottom - len);
        if (i % 2 == 0) label(cr, -i * step + 1.5, bottom - at, -i * 10);
    }
    for (int i = 0; i < 15; i++) {
        line(cr, left, -i * step, left + len, -i * step);
        if (i % 2 == 0) label(cr, left + at, -i * step - 1.5, i * 10);
    }
    for (int i = 1; i < 15; i++) {
        line(cr, left, i * step, left + len, i * step);
        if (i % 2 == 0) label(cr, left + at, i * step - 1.5, -i * 10);
    }
    cairo_set_source_rgba(cr, 0, 0, 0, 1);
    cairo_move_to(cr, 0, bottom);
    cairo_line_to(cr, 0, bottom - len);
    cairo_move_to(cr, left, 0);
    cairo_line_to(cr, left + len, 0);
    cairo_stroke(cr);
}

/* A FreeType face and its library, freed together when cairo destroys the
 * font face that holds them. */
struct ft_hold {
    FT_Library lib;
    FT_Face face;
};

void release_face(void *p)
{
    ft_hold *h = static_cast<ft_hold *>(p);
    if (h->face) FT_Done_Face(h->face);
    FT_Done_FreeType(h->lib);
    delete h;
}

/* The file and face index fontconfig matches for cairo's default toy face
 * (its _cairo_ft_font_face_create_for_toy: family "", roman, medium;
 * substitutions, then the best match); false when none. */
bool default_font(char *file, size_t len, int *index)
{
    FcConfig *config = FcInitLoadConfigAndFonts();
    if (!config) return false;
    bool found = false;
    FcPattern *pat = FcPatternCreate();
    if (pat && FcPatternAddString(pat, FC_FAMILY, reinterpret_cast<const FcChar8 *>("")) &&
        FcPatternAddInteger(pat, FC_SLANT, FC_SLANT_ROMAN) &&
        FcPatternAddInteger(pat, FC_WEIGHT, FC_WEIGHT_MEDIUM) &&
        FcConfigSubstitute(config, pat, FcMatchPattern)) {
        FcDefaultSubstitute(pat);
        FcResult result;
        FcPattern *match = FcFontMatch(config, pat, &result);
        FcChar8 *f = nullptr;
        if (match && FcPatternGetString(match, FC_FILE, 0, &f) == FcResultMatch && f &&
            std::strlen(reinterpret_cast<const char *>(f)) < len) {
            std::strcpy(file, reinterpret_cast<const char *>(f));
            if (FcPatternGetInteger(match, FC_INDEX, 0, index) != FcResultMatch) *index = 0;
            found = true;
        }
        if (match) FcPatternDestroy(match);
    }
    if (pat) FcPatternDestroy(pat);
    FcConfigDestroy(config);
    return found;
}

/* cairo's default toy face as a FreeType face (see the top of the file);
 * NULL when there is none, and cairo's toy face is used. */
cairo_font_face_t *default_face()
{
    static const cairo_user_data_key_t key = {0};
    char file[4096];
    int index = 0;
    if (!default_font(file, sizeof file, &index)) return nullptr;
    ft_hold *h = new (std::nothrow) ft_hold{nullptr, nullptr};
    if (!h) return nullptr;
    if (FT_Init_FreeType(&h->lib) != 0) {
        delete h;
        return nullptr;
    }
    if (FT_New_Face(h->lib, file, index, &h->face) != 0) {
        h->face = nullptr;
        release_face(h);
        return nullptr;
    }
    cairo_font_face_t *face = cairo_ft_font_face_create_for_ft_face(h->face, 0);
    if (cairo_font_face_status(face) != CAIRO_STATUS_SUCCESS ||
        cairo_font_face_set_user_data(face, &key, h, release_face) != CAIRO_STATUS_SUCCESS) {
        cairo_font_face_destroy(face);
        release_face(h);
        return nullptr;
    }
    return face;
}

void draw_page(cairo_t *cr, const double (*pts)[2], const int *start, int npaths)
{
    cairo_set_source_rgba(cr, 0, 0, 0, 1);
    cairo_set_line_width(cr, 1);
    if (bottom_left(pts, start, npaths)) {
        cairo_translate(cr, margin, page_h - margin);
        outlines(cr, pts, start, npaths);
        cairo_stroke(cr);
        cairo_set_source_rgba(cr, 0, 0, 0, 0.4);
        cairo_translate(cr, -margin, margin);
        cairo_set_font_size(cr, 6);
        cairo_set_line_width(cr, 0.4);
        rulers_from_corner(cr);
        text(cr, points(13), -points(6), 5, about);
    } else {
        cairo_translate(cr, page_w / 2, page_h / 2);
        outlines(cr, pts, start, npaths);
        cairo_stroke(cr);
        cairo_set_source_rgba(cr, 0, 0, 0, 0.4);
        cairo_set_font_size(cr, 6);
        cairo_set_line_width(cr, 0.4);
        rulers_from_centre(cr);
        cairo_set_source_rgba(cr, 0, 0, 0, 0.4);
        text(cr, -page_w / 2 + points(13), page_h / 2 - points(6), 5, about);
    }
}

struct sink {
    FILE *f;
    int error; /* errno of the first failed write, EIO when it set none */
};

cairo_status_t put(void *closure, const unsigned char *data, unsigned int length)
{
    sink *s = static_cast<sink *>(closure);
    errno = 0;
    if (length > 0 && std::fwrite(data, 1, length, s->f) != length) {
        if (!s->error) s->error = errno ? errno : EIO;
        return CAIRO_STATUS_WRITE_ERROR;
    }
    return CAIRO_STATUS_SUCCESS;
}

/* abs((int)v) > limit, openscad's test, without its overflow: a value too
 * large for an int is past any page. */
bool past(double v, double limit)
{
    return std::fabs(std::trunc(v)) > limit;
}

} // namespace

extern "C" int io_pdf_write(FILE *f, const double (*pts)[2], const int *start, int npaths,
                            char *err, size_t errlen)
{
    static const int none[1] = {0};
    if (npaths <= 0) start = none, npaths = 0;
    sink s = {f, 0};
    cairo_surface_t *surface = cairo_pdf_surface_create_for_stream(put, &s, page_w, page_h);
    cairo_status_t status = cairo_surface_status(surface);
    if (status == CAIRO_STATUS_SUCCESS) {
#if CAIRO_VERSION >= CAIRO_VERSION_ENCODE(1, 16, 0)
        cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_TITLE, "");
        cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_CREATOR,
                                       "rayscad " RAYSCAD_VERSION_STRING);
        cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_CREATE_DATE, "");
        cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_MOD_DATE, "");
#endif
        cairo_t *cr = cairo_create(surface);
        cairo_font_face_t *face = default_face();
        if (face) {
            cairo_set_font_face(cr, face);
            cairo_font_face_destroy(face); /* cr holds it now */
        }
        draw_page(cr, pts, start, npaths);
        cairo_show_page(cr);
        status = cairo_status(cr);
        cairo_destroy(cr);
        cairo_surface_finish(surface);
        if (status == CAIRO_STATUS_SUCCESS) status = cairo_surface_status(surface);
    }
    cairo_surface_destroy(surface);
    if (s.error) {
        std::snprintf(err, errlen, "%s", std::strerror(s.error));
        return -1;
    }
    if (status != CAIRO_STATUS_SUCCESS) {
        std::snprintf(err, errlen, "cairo: %s", cairo_status_to_string(status));
        return -1;
    }
    return 0;
}

extern "C" int io_region_fits_pdf_page(const double (*pts)[2], const int *start, int npaths)
{
    if (npaths <= 0) return 1;
    int corner = bottom_left(pts, start, npaths);
    double w = corner ? page_w : page_w / 2, h = corner ? page_h : page_h / 2;
    for (int i = 0; i < npaths; i++)
        for (int k = start[i] + 1; k < start[i + 1]; k++)
            if (past(points(pts[k][0]), w) || past(points(pts[k][1]), h)) return 0;
    return 1;
}
