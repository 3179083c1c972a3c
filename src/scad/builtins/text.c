/*
 * text.c — text(): OpenSCAD 2021.01's arguments and defaults (a string
 * argument that is not a string is taken as absent, as OpenSCAD's
 * lookup_variable_with_default does), its .csg header (with the script
 * HarfBuzz would guess for the text when none is given), the curve
 * resolution it derives from $fn/$fa/$fs (fragments of a circle of radius
 * size, / 8, + 1, at least 2 points per curve), and the outlines from the
 * text service, as region leaves in the call's frame.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "builtins.h"

/* The ISO 15924 script of a code point, as HarfBuzz guesses a segment's
 * script: NULL for the common and inherited ones (digits, punctuation). */
static const char *script_of(unsigned long c)
{
    static const struct {
        unsigned long lo, hi;
        const char *tag;
    } ranges[] = {
        {'A', 'Z', "Latn"},       {'a', 'z', "Latn"},       {0xAA, 0xAA, "Latn"},
        {0xBA, 0xBA, "Latn"},     {0xC0, 0xD6, "Latn"},     {0xD8, 0xF6, "Latn"},
        {0xF8, 0x24F, "Latn"},    {0x250, 0x2AF, "Latn"},   {0x370, 0x3FF, "Grek"},
        {0x400, 0x52F, "Cyrl"},   {0x530, 0x58F, "Armn"},   {0x591, 0x5FF, "Hebr"},
        {0x600, 0x6FF, "Arab"},   {0x700, 0x74F, "Syrc"},   {0x750, 0x77F, "Arab"},
        {0x780, 0x7BF, "Thaa"},   {0x900, 0x97F, "Deva"},   {0x980, 0x9FF, "Beng"},
        {0xA00, 0xA7F, "Guru"},   {0xA80, 0xAFF, "Gujr"},   {0xB80, 0xBFF, "Taml"},
        {0xE00, 0xE7F, "Thai"},   {0x10A0, 0x10FF, "Geor"}, {0x1100, 0x11FF, "Hang"},
        {0x1E00, 0x1EFF, "Latn"}, {0x1F00, 0x1FFF, "Grek"}, {0x3040, 0x309F, "Hira"},
        {0x30A0, 0x30FF, "Kana"}, {0x3400, 0x4DBF, "Hani"}, {0x4E00, 0x9FFF, "Hani"},
        {0xAC00, 0xD7AF, "Hang"}, {0xFB1D, 0xFB4F, "Hebr"}, {0xFB50, 0xFDFF, "Arab"},
        {0xFE70, 0xFEFF, "Arab"}, {0xFF21, 0xFF3A, "Latn"}, {0xFF41, 0xFF5A, "Latn"},
    };
    for (size_t i = 0; i < sizeof ranges / sizeof ranges[0]; i++)
        if (c >= ranges[i].lo && c <= ranges[i].hi) return ranges[i].tag;
    return NULL;
}

static int script_rtl(const char *tag)
{
    static const char *const rtl[] = {"Arab", "Hebr", "Syrc", "Thaa", "Nkoo", "Samr", "Mand",
                                      "Cprt", "Khar", "Phnx", "Lydi", "Avst", "Armi", "Phli",
                                      "Prti", "Sarb", "Orkh", "Mend", "Nbat", "Palm", "Hatr",
                                      "Hung", "Mani", "Phlp", "Adlm", "Rohg", "Sogo", "Sogd"};
    for (size_t i = 0; i < sizeof rtl / sizeof rtl[0]; i++)
        if (strcmp(rtl[i], tag) == 0) return 1;
    return 0;
}

static unsigned long utf8_next(const unsigned char **p)
{
    const unsigned char *s = *p;
    unsigned long c = *s++;
    int more = c >= 0xF0 ? 3 : c >= 0xE0 ? 2 : c >= 0xC0 ? 1 : 0;
    if (more) c &= 0x3F >> more;
    while (more-- && (*s & 0xC0) == 0x80)
        c = (c << 6) | (*s++ & 0x3F);
    *p = s;
    return c;
}

enum {
    TX_TEXT,
    TX_SIZE,
    TX_FONT,
    TX_DIRECTION,
    TX_LANGUAGE,
    TX_SCRIPT,
    TX_HALIGN,
    TX_VALIGN,
    TX_SPACING
};

/* The string parameters as given (borrowed), NULL when not strings. */
typedef struct text_args {
    const char *text, *font, *direction, *language, *script, *halign, *valign;
    size_t text_len;
    double size, spacing;
    scad_facet_params f;
} text_args;

static const char *str_arg(scad_call *c, int i)
{
    scad_value v = c->arg[i];
    return v.kind == SV_STR ? v.u.str->s : NULL;
}

static void text_read(scad_call *c, void *out)
{
    text_args *p = out;
    p->text = str_arg(c, TX_TEXT);
    p->text_len = p->text ? c->arg[TX_TEXT].u.str->len : 0;
    p->font = str_arg(c, TX_FONT);
    p->direction = str_arg(c, TX_DIRECTION);
    p->language = str_arg(c, TX_LANGUAGE);
    p->script = str_arg(c, TX_SCRIPT);
    p->halign = str_arg(c, TX_HALIGN);
    p->valign = str_arg(c, TX_VALIGN);
    p->size = 10;
    scad_arg_num(c->arg[TX_SIZE], &p->size);
    p->spacing = 1;
    scad_arg_num(c->arg[TX_SPACING], &p->spacing);
    p->f = scad_facets_read(c);
}

/* text()'s strings in .csg: quoted as they are (2021.01 escapes nothing). */
static void print_raw(scad_buf *b, const char *s, size_t n)
{
    scad_buf_put(b, "\"", 1);
    scad_buf_put(b, s, n);
    scad_buf_put(b, "\"", 1);
}

static void print_str(scad_buf *b, const char *label, const char *s, const char *dflt)
{
    scad_buf_puts(b, label);
    if (!s) s = dflt;
    print_raw(b, s, strlen(s));
}

/* hb_direction_from_string then _to_string: only the first letter counts
 * ("ltl" is "ltr"); NULL when it names no direction. */
static const char *direction_of(const char *s)
{
    switch (s && s[0] ? s[0] | 0x20 : 0) {
    case 'l':
        return "ltr";
    case 'r':
        return "rtl";
    case 't':
        return "ttb";
    case 'b':
        return "btt";
    default:
        return NULL;
    }
}

static int text_print(scad_call *c, const void *args, scad_buf *b)
{
    const text_args *p = args;
    (void)c;
    char script[8] = "";
    if (p->script && p->script[0]) {
        /* hb_script_from_string: four letters, the first upper case */
        size_t n = strlen(p->script) < 4 ? strlen(p->script) : 4;
        for (size_t i = 0; i < 4; i++) {
            char ch = i < n ? p->script[i] : ' ';
            if (ch >= 'A' && ch <= 'Z' && i > 0) ch = (char)(ch + 32);
            if (ch >= 'a' && ch <= 'z' && i == 0) ch = (char)(ch - 32);
            script[i] = ch;
        }
        script[4] = 0;
    } else if (p->text) {
        const unsigned char *s = (const unsigned char *)p->text, *end = s + p->text_len;
        while (s < end) {
            const char *tag = script_of(utf8_next(&s));
            if (tag) {
                memcpy(script, tag, 5);
                break;
            }
        }
    }
    scad_buf_puts(b, "text(text = ");
    print_raw(b, p->text ? p->text : "", p->text_len);
    scad_buf_puts(b, ", size = ");
    scad_print_g(b, p->size);
    scad_buf_puts(b, ", spacing = ");
    scad_print_g(b, p->spacing);
    print_str(b, ", font = ", p->font, "");
    print_str(b, ", direction = ", direction_of(p->direction),
              script[0] && script_rtl(script) ? "rtl" : "ltr");
    print_str(b, ", language = ", p->language && p->language[0] ? p->language : NULL, "en");
    if (script[0]) print_str(b, ", script = ", script, "");
    print_str(b, ", halign = ", p->halign, "left");
    print_str(b, ", valign = ", p->valign, "baseline");
    scad_print_facets(b, p->f, ", ", ")");
    return 0;
}

static scad_geom *text_build(scad_call *c, const void *args)
{
    const text_args *a = args;
    scad_eval *ev = c->ev;
    scad_call_children(c, NULL); /* text() takes none */
    scad_text_params p;
    p.text = a->text ? a->text : "";
    p.size = a->size;
    p.font = a->font ? a->font : "";
    p.direction = a->direction ? a->direction : "";
    p.language = a->language ? a->language : "en";
    p.script = a->script ? a->script : "";
    p.halign = a->halign ? a->halign : "left";
    p.valign = a->valign ? a->valign : "baseline";
    p.spacing = a->spacing;
    int n = scad_fragments(p.size, a->f);
    p.segments = (int)fmax(floor(n / 8.0) + 1, 2);
    p.font_files = ev->top ? ev->top->fonts : NULL;
    p.nfont_files = ev->top ? ev->top->nfonts : 0;
    if (!*p.text || !isfinite(p.size) || !isfinite(p.spacing)) return NULL;
    const scad_services *s = ev->services;
    if (!s->text) {
        scad_eval_error(ev, c->st->loc, "text() is not available here (no font service)");
        return NULL;
    }
    scad_paths out = {NULL, NULL, 0};
    char err[256];
    int rc = s->text(s->ud, &p, &out, err, sizeof err);
    if (rc > 0) { /* OpenSCAD draws nothing and goes on */
        scad_diag_warning(ev->d, c->st->loc, "text(): %s; nothing is drawn", err);
        return NULL;
    }
    if (rc != 0) {
        scad_eval_error(ev, c->st->loc, "text(): %s", err);
        return NULL;
    }
    scad_geom *g = scad_region_geom(ev, &out, c->state);
    scad_paths_free(&out);
    return g;
}

static const char *const text_params[] = {"text",   "size",   "font",   "direction", "language",
                                          "script", "halign", "valign", "spacing",   NULL};
static const scad_module_def text = {"text",    text_params, 3,         sizeof(text_args),
                                     text_read, text_print,  text_build};

const scad_module_def *const scad_text_modules[] = {&text, NULL};
