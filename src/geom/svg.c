/*
 * svg.c — the geometry of OpenSCAD 2021.01's libsvg, in C: path data,
 * basic shapes, transforms, lengths and the page placement of import_svg.
 *
 * libsvg's readings are kept with their quirks, since OpenSCAD's output is
 * the reference: numbers are whole attribute values or 0 (no units on
 * coordinates), path data is split on spaces and commas with the command
 * letters and '-' kept as tokens (so "1e-5" is put back together), circles
 * and ellipses have 40 points, Bézier curves 20, arcs |Δθ|·10/π + 4 steps;
 * an open subpath is stroked (the caller widens it) — a path that closed
 * any subpath with Z keeps its last open one as an outline; a rounded rect
 * goes through path data printed with 6 significant digits, as
 * boost::format prints it.
 *
 * Invariant: every point stored is finite (a point that is not — an arc of
 * radius 0, an overflow — is dropped), and the document holds at most
 * GEOM_SVG_MAX_POINTS points.
 */
#include "svg.h"
#include "../intervals/angles.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

/* ---- growing the document ---------------------------------------------------- */

static int grow(void **p, int *cap, int need, size_t elem)
{
    if (need <= *cap) return 0;
    int c = *cap ? *cap : 64;
    while (c < need)
        c *= 2;
    void *q = realloc(*p, (size_t)c * elem);
    if (!q) return -1;
    *p = q;
    *cap = c;
    return 0;
}

/* Starts a new path (stroke: an open line to widen); 0 or -1. */
static int path_begin(geom_svg *d, int stroke)
{
    if (d->npaths + 2 > d->cappaths) {
        int c = d->cappaths ? 2 * d->cappaths : 64;
        int *st = realloc(d->start, (size_t)c * sizeof *st);
        if (!st) return -1;
        d->start = st;
        unsigned char *k = realloc(d->stroke, (size_t)c);
        if (!k) return -1;
        d->stroke = k;
        d->cappaths = c;
    }
    if (d->npaths == 0) d->start[0] = d->npts;
    d->start[d->npaths + 1] = d->npts;
    d->stroke[d->npaths] = (unsigned char)stroke;
    d->npaths++;
    return 0;
}

/* Appends (x, y) to the last path; a point that is not finite, or past
 * the cap, is dropped.  0 or -1. */
static int point(geom_svg *d, double x, double y)
{
    if (!isfinite(x) || !isfinite(y) || d->npts >= GEOM_SVG_MAX_POINTS) return 0;
    if (grow((void **)&d->pts, &d->cappts, d->npts + 1, sizeof *d->pts)) return -1;
    d->pts[d->npts][0] = x;
    d->pts[d->npts][1] = y;
    d->npts++;
    d->start[d->npaths] = d->npts;
    return 0;
}

static int path_len(const geom_svg *d, int i)
{
    return d->start[i + 1] - d->start[i];
}

/* Drops the last path (it must be the last one started). */
static void path_drop(geom_svg *d)
{
    d->npaths--;
    d->npts = d->start[d->npaths];
}

/* ---- numbers and lengths ----------------------------------------------------- */

/* boost::spirit's real parser over the whole of s[0 .. n): sign, digits
 * with an optional point, optional exponent; "nan", "inf", "infinity".
 * 1 and *out, or 0. */
static int real(const char *s, size_t n, double *out)
{
    char buf[128];
    if (n == 0 || n >= sizeof buf) return 0;
    memcpy(buf, s, n);
    buf[n] = 0;
    const char *p = buf;
    if (*p == '+' || *p == '-') p++;
    const char *body = p;
    if (!strcasecmp(body, "nan") || !strcasecmp(body, "inf") || !strcasecmp(body, "infinity")) {
        *out = strtod(buf, NULL);
        return 1;
    }
    int digits = 0;
    while (isdigit((unsigned char)*p))
        p++, digits++;
    if (*p == '.') {
        p++;
        while (isdigit((unsigned char)*p))
            p++, digits++;
    }
    if (!digits) return 0;
    if (*p == 'e' || *p == 'E') {
        const char *q = p + 1;
        if (*q == '+' || *q == '-') q++;
        if (isdigit((unsigned char)*q)) {
            while (isdigit((unsigned char)*q))
                q++;
            p = q;
        }
    }
    if (*p) return 0;
    *out = strtod(buf, NULL);
    return 1;
}

double geom_svg_number(const char *text)
{
    double v;
    return text && real(text, strlen(text), &v) ? v : 0;
}

/* The longest prefix of s that the real parser takes: its length. */
static size_t real_prefix(const char *s, double *out)
{
    size_t n = strlen(s);
    for (size_t k = n < 127 ? n : 127; k > 0; k--)
        if (real(s, k, out)) return k;
    return 0;
}

geom_svg_length geom_svg_parse_length(const char *text)
{
    static const char *const units[] = {"em", "ex", "px", "in", "cm", "mm", "pt", "pc", "%"};
    static const geom_svg_unit kinds[] = {
        GEOM_SVG_UNIT_EM, GEOM_SVG_UNIT_EX, GEOM_SVG_UNIT_PX,
        GEOM_SVG_UNIT_IN, GEOM_SVG_UNIT_CM, GEOM_SVG_UNIT_MM,
        GEOM_SVG_UNIT_PT, GEOM_SVG_UNIT_PC, GEOM_SVG_UNIT_PERCENT};
    geom_svg_length r = {0, GEOM_SVG_UNIT_UNDEFINED};
    if (!text) return r;
    const char *p = text;
    while (isspace((unsigned char)*p))
        p++;
    double v;
    size_t k = real_prefix(p, &v);
    if (!k) return r;
    p += k;
    while (isspace((unsigned char)*p))
        p++;
    geom_svg_unit u = GEOM_SVG_UNIT_NONE;
    for (size_t i = 0; i < sizeof units / sizeof *units; i++) {
        size_t l = strlen(units[i]);
        if (!strncmp(p, units[i], l)) {
            u = kinds[i];
            p += l;
            break;
        }
    }
    while (isspace((unsigned char)*p))
        p++;
    if (*p) return r;
    r.number = v;
    r.unit = u;
    return r;
}

/* parse_viewbox: four numbers, commas or spaces between, width and height
 * not negative. */
static int parse_viewbox(const char *text, double vb[4])
{
    if (!text) return 0;
    const char *p = text;
    for (int i = 0; i < 4; i++) {
        while (isspace((unsigned char)*p))
            p++;
        if (i > 0 && *p == ',') {
            p++;
            while (isspace((unsigned char)*p))
                p++;
        }
        size_t k = real_prefix(p, &vb[i]);
        if (!k) return 0;
        p += k;
    }
    while (isspace((unsigned char)*p))
        p++;
    return *p == 0 && vb[2] >= 0 && vb[3] >= 0;
}

/* parse_alignment: [defer] <align> [meet|slice]; xMidYMid meet unless
 * the whole text reads so. */
static void parse_alignment(const char *text, geom_svg_page *pg)
{
    static const char *const names[] = {"xMinYMin", "xMidYMin", "xMaxYMin", "xMinYMid", "xMidYMid",
                                        "xMaxYMid", "xMinYMax", "xMidYMax", "xMaxYMax"};
    pg->align_x = pg->align_y = GEOM_SVG_ALIGN_MID;
    pg->meet = 1;
    if (!text) return;
    char w[3][32];
    int n = 0;
    const char *p = text;
    while (*p && n < 4) {
        while (isspace((unsigned char)*p))
            p++;
        if (!*p) break;
        size_t l = 0;
        while (p[l] && !isspace((unsigned char)p[l]))
            l++;
        if (n == 3 || l >= sizeof w[0]) return;
        memcpy(w[n], p, l);
        w[n][l] = 0;
        n++;
        p += l;
    }
    int i = 0;
    if (n > 0 && !strcmp(w[0], "defer")) i++;
    if (i >= n) return;
    int ax = -1, ay = -1;
    if (!strcmp(w[i], "none")) {
        ax = ay = GEOM_SVG_ALIGN_NONE;
    } else {
        for (int k = 0; k < 9; k++)
            if (!strcmp(w[i], names[k])) {
                ax = GEOM_SVG_ALIGN_MIN + k % 3;
                ay = GEOM_SVG_ALIGN_MIN + k / 3;
            }
    }
    if (ax < 0) return;
    int meet = 1;
    if (i + 1 < n) {
        if (strcmp(w[i + 1], "meet") && strcmp(w[i + 1], "slice")) return;
        meet = !strcmp(w[i + 1], "meet");
        if (i + 2 < n) return;
    }
    pg->align_x = ax;
    pg->align_y = ay;
    pg->meet = meet;
}

/* ---- transforms -------------------------------------------------------------- */

/* out = a · b (2×3 affine matrices, a b c d e f). */
static void mul(const double a[6], const double b[6], double out[6])
{
    double r[6] = {a[0] * b[0] + a[2] * b[1],        a[1] * b[0] + a[3] * b[1],
                   a[0] * b[2] + a[2] * b[3],        a[1] * b[2] + a[3] * b[3],
                   a[0] * b[4] + a[2] * b[5] + a[4], a[1] * b[4] + a[3] * b[5] + a[5]};
    memcpy(out, r, sizeof r);
}

/* The matrix of one transform op with its arguments; 0 when the argument
 * count is wrong (libsvg then leaves the op out). */
static int op_matrix(char op, const double *a, int n, double m[6])
{
    double id[6] = {1, 0, 0, 1, 0, 0};
    memcpy(m, id, sizeof id);
    switch (op) {
    case 'm':
        if (n != 6) return 0;
        memcpy(m, a, 6 * sizeof *a);
        return 1;
    case 't':
        if (n < 1 || n > 2) return 0;
        m[4] = a[0];
        m[5] = n > 1 ? a[1] : 0;
        return 1;
    case 's':
        if (n < 1 || n > 2) return 0;
        m[0] = a[0];
        m[3] = n > 1 ? a[1] : a[0];
        return 1;
    case 'r': {
        if (n != 1 && n != 3) return 0;
        double c = iv_cos_degrees(a[0]), s = iv_sin_degrees(a[0]);
        double r[6] = {c, s, -s, c, 0, 0};
        if (n == 3) {
            double to[6] = {1, 0, 0, 1, a[1], a[2]}, back[6] = {1, 0, 0, 1, -a[1], -a[2]};
            mul(to, r, r);
            mul(r, back, r);
        }
        memcpy(m, r, sizeof r);
        return 1;
    }
    case 'x':
        if (n != 1) return 0;
        m[2] = iv_tan_degrees(a[0]);
        return 1;
    case 'y':
        if (n != 1) return 0;
        m[1] = iv_tan_degrees(a[0]);
        return 1;
    }
    return 0;
}

void geom_svg_transform(const char *text, const double m[6], double out[6])
{
    static const char *const names[] = {"matrix", "translate", "scale", "rotate", "skewX", "skewY"};
    static const char letters[] = "mtsrxy";
    memcpy(out, m, 6 * sizeof *m);
    if (!text || !*text) return;
    /* libsvg's boost::replace_all of each name by its letter, in order */
    size_t n = strlen(text);
    char *s = malloc(n + 1);
    if (!s) return;
    memcpy(s, text, n + 1);
    for (int k = 0; k < 6; k++) {
        size_t l = strlen(names[k]);
        char *w = s;
        for (char *r = s; *r;) {
            if (!strncmp(r, names[k], l)) {
                *w++ = letters[k];
                r += l;
            } else {
                *w++ = *r++;
            }
        }
        *w = 0;
    }
    /* tokens: " ,()" separate, the letters are tokens of their own */
    char op = 0;
    double args[16];
    int nargs = 0;
    for (const char *p = s;;) {
        while (*p && strchr(" ,()", *p))
            p++;
        int end = !*p;
        int is_op = !end && strchr(letters, *p);
        if (end || is_op) {
            double t[6];
            if (op && op_matrix(op, args, nargs, t)) mul(out, t, out);
            if (end) break;
            op = *p++;
            nargs = 0;
            continue;
        }
        size_t l = 0;
        while (p[l] && !strchr(" ,()", p[l]) && !strchr(letters, p[l]))
            l++;
        double v = 0;
        if (!real(p, l, &v)) v = 0;
        if (op && nargs < 16)
            args[nargs++] = v;
        else if (op)
            nargs++; /* too many: the op is left out */
        p += l;
    }
    free(s);
}

/* ---- path data --------------------------------------------------------------- */

/* libsvg's is_open_path: the ends further apart than 0.1. */
static int is_open(const geom_svg *d, int i)
{
    int a = d->start[i], b = d->start[i + 1] - 1;
    if (b < a) return 0;
    return hypot(d->pts[a][0] - d->pts[b][0], d->pts[a][1] - d->pts[b][1]) > 0.1;
}

/* The SVG implementation notes' endpoint-to-centre arc (F.6.5), in steps
 * of at most π/10, from (x1, y1) (not added) to (x2, y2). */
static int arc_to(geom_svg *d, double x1, double y1, double rx, double ry, double x2, double y2,
                  double angle, int large, int sweep)
{
    double cr = cos(IV_PI * angle / 180.0), sr = sin(IV_PI * angle / 180.0);
    double dx = (x1 - x2) / 2, dy = (y1 - y2) / 2;
    double x1_ = cr * dx + sr * dy, y1_ = -sr * dx + cr * dy;
    double l = (x1_ * x1_) / (rx * rx) + (y1_ * y1_) / (ry * ry);
    if (l > 1) {
        rx = fabs(sqrt(l) * rx);
        ry = fabs(sqrt(l) * ry);
    }
    double t1 = rx * rx * ry * ry - rx * rx * y1_ * y1_ - ry * ry * x1_ * x1_;
    double t2 = rx * rx * y1_ * y1_ + ry * ry * x1_ * x1_;
    if (t1 < 0) t1 = 0;
    double t3 = sqrt(t1 / t2);
    if (large == sweep) t3 = -t3;
    double cx_ = t3 * rx * y1_ / ry, cy_ = t3 * -ry * x1_ / rx;
    double cx = cr * cx_ - sr * cy_ + (x1 + x2) / 2.0;
    double cy = sr * cx_ + cr * cy_ + (y1 + y2) / 2.0;
    double ux = (x1_ - cx_) / rx, uy = (y1_ - cy_) / ry;
    double vx = (-x1_ - cx_) / rx, vy = (-y1_ - cy_) / ry;
    double theta = atan2(uy, ux);
    if (theta < 0) theta += 2 * IV_PI;
    double delta = atan2(vy, vx) - atan2(uy, ux);
    if (delta < 0) delta += 2 * IV_PI;
    if (!sweep) delta -= 2 * IV_PI;
    if (!isfinite(delta)) return 0; /* a radius of 0: libsvg's points are NaN */
    int steps = (int)(fabs(delta) * 10.0 / IV_PI + 4);
    for (int a = 0; a <= steps; a++) {
        double phi = theta + delta * a / steps;
        double xx = cr * cos(phi) * rx - sr * sin(phi) * ry;
        double yy = sr * cos(phi) * rx + cr * sin(phi) * ry;
        if (point(d, xx + cx, yy + cy)) return -1;
    }
    return 0;
}

static double t_pow(double a, int e)
{
    double r = 1;
    for (int i = 0; i < e; i++)
        r *= 1 - a;
    return r;
}

/* A quadratic (cx2 unused) or cubic Bézier from (x, y) in 20 steps. */
static int curve_to(geom_svg *d, int cubic, double x, double y, double cx1, double cy1, double cx2,
                    double cy2, double x2, double y2)
{
    for (int idx = 1; idx <= 20; idx++) {
        double a = idx * (1.0 / 20.0), xx, yy;
        if (cubic) {
            xx = x * t_pow(a, 3) + cx1 * 3 * t_pow(a, 2) * a + cx2 * 3 * t_pow(a, 1) * a * a +
                 x2 * a * a * a;
            yy = y * t_pow(a, 3) + cy1 * 3 * t_pow(a, 2) * a + cy2 * 3 * t_pow(a, 1) * a * a +
                 y2 * a * a * a;
        } else {
            xx = x * t_pow(a, 2) + cx1 * 2 * t_pow(a, 1) * a + x2 * a * a;
            yy = y * t_pow(a, 2) + cy1 * 2 * t_pow(a, 1) * a + y2 * a * a;
        }
        if (point(d, xx, yy)) return -1;
    }
    return 0;
}

/* Marks the last path as a line to stroke. */
static void mark_stroke(geom_svg *d)
{
    d->stroke[d->npaths - 1] = 1;
}

/* libsvg's path::set_attrs over the data text; the shape's paths start at
 * path `first`. */
static int path_data(geom_svg *d, const char *data, int first)
{
    static const char kept[] = "-zmlcqahvstZMLCQAHVST";
    double x = 0, y = 0, xx = 0, yy = 0, rx = 0, ry = 0, cx1 = 0, cy1 = 0, cx2 = 0, cy2 = 0;
    double angle = 0;
    int large = 0, sweep = 0, last_cubic = 0, last_quad = 0, point_no = 0, negate = 0;
    int closed = 0;
    char cmd = ' ';
    char exp[160] = "";
    if (path_begin(d, 0)) return -1;
    for (const char *s = data ? data : ""; *s;) {
        while (*s == ' ' || *s == ',')
            s++;
        if (!*s) break;
        size_t l = strchr(kept, *s) ? 1 : 0;
        if (!l)
            while (s[l] && s[l] != ' ' && s[l] != ',' && !strchr(kept, s[l]))
                l++;
        double p = 0;
        if (l == 1 && strchr(kept, *s)) {
            if (*s == '-') {
                negate = 1;
                s++;
                continue;
            }
            point_no = -1;
            cmd = *s;
        } else if (s[l - 1] == 'e') {
            snprintf(exp, sizeof exp, "%s%.*s", negate ? "-" : "", (int)(l < 120 ? l : 120), s);
            negate = 0;
            s += l;
            continue;
        } else {
            if (!exp[0]) {
                if (!real(s, l, &p)) p = 0;
                if (negate) p = -p;
            } else {
                char buf[300];
                int k = snprintf(buf, sizeof buf, "%s%s%.*s", exp, negate ? "-" : "",
                                 (int)(l < 120 ? l : 120), s);
                if (k < 0 || !real(buf, (size_t)k < sizeof buf ? (size_t)k : 0, &p)) p = 0;
                exp[0] = 0;
            }
            negate = 0;
        }
        s += l;
        int rel = islower((unsigned char)cmd);
        switch (cmd) {
        case 'a':
        case 'A':
            switch (point_no) {
            case 0:
                rx = fabs(p);
                break;
            case 1:
                ry = fabs(p);
                break;
            case 2:
                angle = p;
                break;
            case 3:
                large = p > 0.5;
                break;
            case 4:
                sweep = p > 0.5;
                break;
            case 5:
                xx = rel ? x + p : p;
                break;
            case 6:
                yy = rel ? y + p : p;
                if (arc_to(d, x, y, rx, ry, xx, yy, angle, large, sweep)) return -1;
                x = xx;
                y = yy;
                point_no = -1;
                last_cubic = last_quad = 0;
                break;
            }
            break;
        case 'l':
        case 'L':
            switch (point_no) {
            case 0:
                xx = rel ? x + p : p;
                break;
            case 1:
                yy = rel ? y + p : p;
                if (point(d, xx, yy)) return -1;
                x = xx;
                y = yy;
                point_no = -1;
                last_cubic = last_quad = 0;
                break;
            }
            break;
        case 'c':
        case 'C':
            switch (point_no) {
            case 0:
                cx1 = p;
                break;
            case 1:
                cy1 = p;
                break;
            case 2:
                cx2 = p;
                break;
            case 3:
                cy2 = p;
                break;
            case 4:
                xx = rel ? x + p : p;
                break;
            case 5:
                yy = rel ? y + p : p;
                if (rel) {
                    cx1 += x;
                    cy1 += y;
                    cx2 += x;
                    cy2 += y;
                }
                if (curve_to(d, 1, x, y, cx1, cy1, cx2, cy2, xx, yy)) return -1;
                x = xx;
                y = yy;
                point_no = -1;
                last_cubic = 1;
                last_quad = 0;
                break;
            }
            break;
        case 's':
        case 'S':
            switch (point_no) {
            case 0:
                if (last_cubic) {
                    cx1 = x + (x - cx2);
                    cy1 = y + (y - cy2);
                } else {
                    cx1 = x;
                    cy1 = y;
                }
                cx2 = p;
                break;
            case 1:
                cy2 = p;
                break;
            case 2:
                xx = rel ? x + p : p;
                break;
            case 3:
                yy = rel ? y + p : p;
                if (rel) {
                    cx2 += x;
                    cy2 += y;
                }
                if (curve_to(d, 1, x, y, cx1, cy1, cx2, cy2, xx, yy)) return -1;
                x = xx;
                y = yy;
                point_no = -1;
                last_cubic = 1;
                last_quad = 0;
                break;
            }
            break;
        case 'q':
        case 'Q':
            switch (point_no) {
            case 0:
                cx1 = p;
                break;
            case 1:
                cy1 = p;
                break;
            case 2:
                xx = rel ? x + p : p;
                break;
            case 3:
                yy = rel ? y + p : p;
                if (rel) {
                    cx1 += x;
                    cy1 += y;
                }
                if (curve_to(d, 0, x, y, cx1, cy1, 0, 0, xx, yy)) return -1;
                x = xx;
                y = yy;
                point_no = -1;
                last_cubic = 0;
                last_quad = 1;
                break;
            }
            break;
        case 't':
        case 'T':
            switch (point_no) {
            case 0:
                if (last_quad) {
                    cx1 = x + (x - cx1);
                    cy1 = y + (y - cy1);
                } else {
                    cx1 = x;
                    cy1 = y;
                }
                xx = rel ? x + p : p;
                break;
            case 1:
                yy = rel ? y + p : p;
                if (curve_to(d, 0, x, y, cx1, cy1, 0, 0, xx, yy)) return -1;
                x = xx;
                y = yy;
                point_no = -1;
                last_cubic = 0;
                last_quad = 1;
                break;
            }
            break;
        case 'm':
        case 'M':
            switch (point_no) {
            case 0:
                xx = rel ? x + p : p;
                break;
            case 1:
                yy = rel ? y + p : p;
                cmd = rel ? 'l' : 'L';
                if (path_len(d, d->npaths - 1) > 0) {
                    if (is_open(d, d->npaths - 1)) mark_stroke(d);
                    if (path_begin(d, 0)) return -1;
                }
                if (point(d, xx, yy)) return -1;
                x = xx;
                y = yy;
                point_no = -1;
                last_cubic = last_quad = 0;
                break;
            }
            break;
        case 'v':
        case 'V':
            if (point_no == 0) {
                y = rel ? y + p : p;
                if (point(d, x, y)) return -1;
                point_no = -1;
                last_cubic = last_quad = 0;
            }
            break;
        case 'h':
        case 'H':
            if (point_no == 0) {
                x = rel ? x + p : p;
                if (point(d, x, y)) return -1;
                point_no = -1;
                last_cubic = last_quad = 0;
            }
            break;
        case 'z':
        case 'Z': {
            int i = d->npaths - 1;
            if (path_len(d, i) > 0) {
                double fx = d->pts[d->start[i]][0], fy = d->pts[d->start[i]][1];
                if (point(d, fx, fy)) return -1;
                x = fx;
                y = fy;
            }
            if (path_begin(d, 0)) return -1;
            closed = 1;
            last_cubic = last_quad = 0;
            break;
        }
        }
        point_no++;
    }
    while (d->npaths > first && path_len(d, d->npaths - 1) == 0)
        path_drop(d);
    if (!closed && d->npaths > first && is_open(d, d->npaths - 1)) mark_stroke(d);
    return 0;
}

/* ---- shapes ------------------------------------------------------------------ */

typedef struct attrs {
    geom_svg_attr_fn get;
    void *ud;
} attrs;

static const char *attr(const attrs *a, const char *name)
{
    return a->get(a->ud, name);
}

static double num(const attrs *a, const char *name)
{
    return geom_svg_number(attr(a, name));
}

/* shape::get_style: the value of name in the style attribute, split at
 * ';' then ':' (exactly two parts, nothing trimmed), or "". */
static void style(const attrs *a, const char *name, char *out, size_t n)
{
    out[0] = 0;
    const char *s = attr(a, "style");
    if (!s) return;
    size_t ln = strlen(name);
    for (const char *p = s;;) {
        const char *e = strchr(p, ';');
        size_t l = e ? (size_t)(e - p) : strlen(p);
        const char *colon = memchr(p, ':', l);
        if (colon && !memchr(colon + 1, ':', l - (size_t)(colon + 1 - p)) &&
            (size_t)(colon - p) == ln && !strncmp(p, name, ln)) {
            size_t vl = l - ln - 1;
            if (vl >= n) vl = n - 1;
            memcpy(out, colon + 1, vl);
            out[vl] = 0;
            return;
        }
        if (!e) return;
        p = e + 1;
    }
}

static double stroke_width(const attrs *a)
{
    const char *w = attr(a, "stroke-width");
    double v;
    if (!w || !*w) {
        char buf[128];
        style(a, "stroke-width", buf, sizeof buf);
        v = geom_svg_number(buf);
    } else {
        v = geom_svg_number(w);
    }
    return v < 0.01 ? 1 : v;
}

static int stroke_cap(const attrs *a)
{
    const char *c = attr(a, "stroke-linecap");
    char buf[64];
    if (!c || !*c) {
        style(a, "stroke-linecap", buf, sizeof buf);
        c = buf;
    }
    if (!strcmp(c, "butt")) return GEOM_SVG_CAP_BUTT;
    if (!strcmp(c, "round")) return GEOM_SVG_CAP_ROUND;
    return GEOM_SVG_CAP_SQUARE;
}

/* draw_ellipse: 40 points, from angle 2π/40 to 2π, x by sin. */
static int ellipse(geom_svg *d, double x, double y, double rx, double ry)
{
    if (path_begin(d, 0)) return -1;
    for (int idx = 1; idx <= 40; idx++) {
        double a = idx * (2 * IV_PI / 40.0);
        if (point(d, rx * sin(a) + x, ry * cos(a) + y)) return -1;
    }
    return 0;
}

/* The points attribute of polyline and polygon: numbers in pairs (an odd
 * last one dropped). */
static int points(geom_svg *d, const char *text)
{
    int first = 1;
    double px = 0;
    for (const char *s = text ? text : ""; *s;) {
        while (*s == ' ' || *s == ',')
            s++;
        if (!*s) break;
        size_t l = 0;
        while (s[l] && s[l] != ' ' && s[l] != ',')
            l++;
        double v;
        if (!real(s, l, &v)) v = 0;
        s += l;
        if (first)
            px = v;
        else if (point(d, px, v))
            return -1;
        first = !first;
    }
    return 0;
}

static int rect(geom_svg *d, const attrs *a, int first)
{
    double x = num(a, "x"), y = num(a, "y"), w = num(a, "width"), h = num(a, "height");
    double rx = num(a, "rx"), ry = num(a, "ry");
    int has_rx = !(fabs(rx) < 1e-8), has_ry = !(fabs(ry) < 1e-8);
    if (!has_rx && !has_ry) {
        if (path_begin(d, 0) || point(d, x, y) || point(d, x + w, y) || point(d, x + w, y + h) ||
            point(d, x, y + h) || point(d, x, y))
            return -1;
        return 0;
    }
    if (!has_rx)
        rx = ry;
    else if (!has_ry)
        ry = rx;
    if (rx > w / 2) rx = w / 2;
    if (ry > h / 2) ry = h / 2;
    char buf[1024];
    snprintf(buf, sizeof buf,
             "M %g,%g H %g A %g,%g 0 0,1 %g,%g V %g A %g,%g 0 0,1 %g,%g H %g A %g,%g 0 0,1 %g,%g "
             "V %g A %g,%g 0 0,1 %g,%g z",
             x + rx, y, x + w - rx, rx, ry, x + w, y + ry, y + h - ry, rx, ry, x + w - rx, y + h,
             x + rx, rx, ry, x, y + h - ry, y + ry, rx, ry, x + rx, y);
    return path_data(d, buf, first);
}

int geom_svg_add_element(geom_svg *d, const char *name, geom_svg_attr_fn get, void *ud,
                         const double m[6])
{
    static const char *const kinds[] = {"path",     "rect",    "circle", "ellipse", "line",
                                        "polyline", "polygon", "svg",    "g",       NULL};
    int kind = -1;
    for (int k = 0; kinds[k]; k++)
        if (!strcmp(name, kinds[k])) kind = k;
    if (kind < 0) return 0;
    attrs a = {get, ud};
    if (kind == 7) {
        geom_svg_page pg;
        memset(&pg, 0, sizeof pg);
        pg.width = geom_svg_parse_length(attr(&a, "width"));
        pg.height = geom_svg_parse_length(attr(&a, "height"));
        pg.vb_valid = parse_viewbox(attr(&a, "viewBox"), pg.vb);
        parse_alignment(attr(&a, "preserveAspectRatio"), &pg);
        if (grow((void **)&d->pages, &d->cappages, d->npages + 1, sizeof *d->pages)) return -1;
        d->pages[d->npages++] = pg;
        return 0;
    }
    if (kind == 8) return 0;
    if (grow((void **)&d->shapes, &d->capshapes, d->nshapes + 1, sizeof *d->shapes)) return -1;
    geom_svg_shape *sh = &d->shapes[d->nshapes];
    if (m) {
        geom_svg_transform(attr(&a, "transform"), m, sh->world_from_local);
    } else {
        static const double id[6] = {1, 0, 0, 1, 0, 0};
        memcpy(sh->world_from_local, id, sizeof id);
    }
    sh->stroke_width = stroke_width(&a);
    sh->cap = stroke_cap(&a);
    sh->page = d->npages - 1;
    int first = d->npaths, rc = 0;
    switch (kind) {
    case 0:
        rc = path_data(d, attr(&a, "d"), first);
        break;
    case 1:
        rc = rect(d, &a, first);
        break;
    case 2: {
        double r = num(&a, "r");
        rc = ellipse(d, num(&a, "cx"), num(&a, "cy"), r, r);
        break;
    }
    case 3:
        rc = ellipse(d, num(&a, "cx"), num(&a, "cy"), num(&a, "rx"), num(&a, "ry"));
        break;
    case 4:
        rc = path_begin(d, 1) || point(d, num(&a, "x1"), num(&a, "y1")) ||
             point(d, num(&a, "x2"), num(&a, "y2"));
        break;
    case 5:
        rc = path_begin(d, 1) || points(d, attr(&a, "points"));
        break;
    case 6: {
        rc = path_begin(d, 0) || points(d, attr(&a, "points"));
        int i = d->npaths - 1;
        if (!rc && path_len(d, i) > 0)
            rc = point(d, d->pts[d->start[i]][0], d->pts[d->start[i]][1]);
        break;
    }
    }
    if (rc) return -1;
    sh = &d->shapes[d->nshapes++];
    sh->first = first;
    sh->count = d->npaths - first;
    return 0;
}

void geom_svg_free(geom_svg *d)
{
    free(d->pts);
    free(d->start);
    free(d->stroke);
    free(d->shapes);
    free(d->pages);
    memset(d, 0, sizeof *d);
}

/* ---- the page ---------------------------------------------------------------- */

#define INCH_TO_MM 25.4

/* import_svg's to_mm. */
static double to_mm(geom_svg_length l, double vb, int vb_valid, double dpi)
{
    switch (l.unit) {
    case GEOM_SVG_UNIT_NONE:
        return INCH_TO_MM * l.number / dpi;
    case GEOM_SVG_UNIT_PX:
        return INCH_TO_MM * l.number / 96.0;
    case GEOM_SVG_UNIT_PT:
        return INCH_TO_MM * l.number / 72.0;
    case GEOM_SVG_UNIT_PC:
        return INCH_TO_MM * l.number / 6.0;
    case GEOM_SVG_UNIT_IN:
        return INCH_TO_MM * l.number;
    case GEOM_SVG_UNIT_CM:
        return 10 * l.number;
    case GEOM_SVG_UNIT_MM:
        return l.number;
    case GEOM_SVG_UNIT_UNDEFINED:
        return vb_valid ? INCH_TO_MM * vb / dpi : 0.0;
    default:
        return vb_valid ? vb : 0.0; /* em, ex, % */
    }
}

static double align_of(int alignment, double page_mm, double scale, double vb)
{
    if (alignment == GEOM_SVG_ALIGN_MID) return page_mm / 2.0 - scale * vb / 2.0;
    if (alignment == GEOM_SVG_ALIGN_MAX) return page_mm - scale * vb;
    return 0.0;
}

/* The page's size in mm, scale and alignment offset. */
static void page_frame(const geom_svg_page *pg, double dpi, double size[2], double s[2],
                       double al[2])
{
    size[0] = to_mm(pg->width, pg->vb[2], pg->vb_valid, dpi);
    size[1] = to_mm(pg->height, pg->vb[3], pg->vb_valid, dpi);
    s[0] = s[1] = 1;
    al[0] = al[1] = 0;
    if (!pg->vb_valid) return;
    s[0] = size[0] / pg->vb[2];
    s[1] = size[1] / pg->vb[3];
    if (pg->align_x == GEOM_SVG_ALIGN_NONE) return;
    double k = pg->meet ? (s[0] < s[1] ? s[0] : s[1]) : (s[0] > s[1] ? s[0] : s[1]);
    s[0] = s[1] = k;
    al[0] = align_of(pg->align_x, size[0], k, pg->vb[2]);
    al[1] = align_of(pg->align_y, size[1], k, pg->vb[3]);
}

void geom_svg_scale(const geom_svg *d, int page, double dpi, double s[2])
{
    s[0] = s[1] = 1;
    if (page < 0 || page >= d->npages) return;
    double size[2], al[2];
    page_frame(&d->pages[page], dpi, size, s, al);
}

void geom_svg_frame_of(const geom_svg *d, double dpi, int center, const double bbox[4],
                       geom_svg_frame *f)
{
    double size[2] = {0, 0}, al[2] = {0, 0};
    f->s[0] = f->s[1] = 1;
    f->vb[0] = f->vb[1] = 0;
    if (d->npages > 0) {
        const geom_svg_page *pg = &d->pages[d->npages - 1];
        page_frame(pg, dpi, size, f->s, al);
        if (pg->vb_valid) {
            f->vb[0] = pg->vb[0];
            f->vb[1] = pg->vb[1];
        }
    }
    if (center) {
        /* Eigen's empty AlignedBox has min +max and max -max: its centre is 0 */
        int empty = bbox[0] > bbox[2];
        f->c[0] = empty ? 0 : (bbox[0] + bbox[2]) / 2;
        f->c[1] = empty ? 0 : (bbox[1] + bbox[3]) / 2;
    } else {
        f->c[0] = -al[0];
        f->c[1] = size[1] - al[1];
    }
}
