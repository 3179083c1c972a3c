/*
 * math.c — OpenSCAD's builtin functions (math, vectors, strings,
 * type tests, rands) with its warnings for wrong argument counts and types.
 *
 * Each builtin reads borrowed arguments and returns an owned value; a wrong
 * type gives undef and "WARNING: f() parameter could not be converted", as
 * OpenSCAD 2021.01 does.  Trigonometry is in degrees and exact at multiples
 * of 30 and 45 degrees where OpenSCAD's sin_degrees/cos_degrees are
 * (src/intervals/angles.c).  registry.c finds them by name.
 */
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "builtins.h"

static void conv_warning(scad_eval *ev, scad_loc loc, const char *name)
{
    scad_diag_warning(ev->d, loc, "%s() parameter could not be converted", name);
}

static void count_warning(scad_eval *ev, scad_loc loc, const char *name)
{
    scad_diag_warning(ev->d, loc, "%s() number of parameters does not match", name);
}

/* n numeric positional arguments into x; warns and returns 0 otherwise. */
static int nums(scad_eval *ev, const scad_argv *a, scad_loc loc, const char *name, int n, double *x)
{
    if (a->n != n) {
        count_warning(ev, loc, name);
        return 0;
    }
    for (int i = 0; i < n; i++) /* all read, then checked */
        scad_arg_at(a, i);
    for (int i = 0; i < n; i++) {
        if (scad_arg_at(a, i).kind != SV_NUM) {
            conv_warning(ev, loc, name);
            return 0;
        }
        x[i] = scad_arg_at(a, i).u.num;
    }
    return 1;
}

/* Degrees, exact at the angles where the answer is exact. */
static scad_value f_unary(scad_eval *ev, const scad_argv *a, scad_loc loc, const char *name)
{
    double x;
    if (!nums(ev, a, loc, name, 1, &x)) return scad_undef();
    switch (name[0]) {
    case 'a':
        if (!strcmp(name, "abs")) return scad_num(fabs(x));
        if (!strcmp(name, "asin")) return scad_num(iv_asin_degrees(x));
        if (!strcmp(name, "acos")) return scad_num(iv_acos_degrees(x));
        return scad_num(iv_atan_degrees(x));
    case 's':
        if (!strcmp(name, "sin")) return scad_num(iv_sin_degrees(x));
        if (!strcmp(name, "sqrt")) return scad_num(sqrt(x));
        return scad_num(x > 0 ? 1.0 : x < 0 ? -1.0 : 0.0); /* sign */
    case 'c':
        if (!strcmp(name, "cos")) return scad_num(iv_cos_degrees(x));
        return scad_num(ceil(x));
    case 't':
        return scad_num(iv_tan_degrees(x));
    case 'f':
        return scad_num(floor(x));
    case 'r':
        return scad_num(round(x));
    case 'e':
        return scad_num(exp(x));
    case 'l':
        return scad_num(log(x)); /* ln */
    }
    return scad_undef();
}

static scad_value f_atan2(scad_eval *ev, const scad_argv *a, scad_loc loc, const char *name)
{
    double x[2];
    if (!nums(ev, a, loc, name, 2, x)) return scad_undef();
    return scad_num(iv_atan2_degrees(x[0], x[1]));
}

static scad_value f_pow(scad_eval *ev, const scad_argv *a, scad_loc loc, const char *name)
{
    double x[2];
    if (!nums(ev, a, loc, name, 2, x)) return scad_undef();
    return scad_num(pow(x[0], x[1]));
}

/* log(x) is log base 10, log(b, x) base b; both as log(x) / log(b). */
static scad_value f_log(scad_eval *ev, const scad_argv *a, scad_loc loc, const char *name)
{
    if (a->n != 1 && a->n != 2) {
        count_warning(ev, loc, name);
        return scad_undef();
    }
    scad_value v0 = scad_arg_at(a, 0);
    if (v0.kind != SV_NUM) {
        conv_warning(ev, loc, name);
        return scad_undef();
    }
    double b = 10.0, x = v0.u.num;
    if (a->n == 2) {
        scad_value v1 = scad_arg_at(a, 1);
        if (v1.kind != SV_NUM) {
            conv_warning(ev, loc, name);
            return scad_undef();
        }
        b = x;
        x = v1.u.num;
    }
    return scad_num(log(x) / log(b));
}

static scad_value f_minmax(scad_eval *ev, const scad_argv *a, scad_loc loc, const char *name)
{
    int is_max = name[1] == 'a';
    if (a->n == 0) {
        count_warning(ev, loc, name);
        return scad_undef();
    }
    scad_value v0 = scad_arg_at(a, 0);
    if (a->n == 1 && v0.kind == SV_VEC && v0.u.vec->n > 0) {
        /* std::min_element / max_element by OpenSCAD's "<": the first
         * extreme wins, values it cannot order never replace it */
        const scad_vec *v = v0.u.vec;
        int best = 0;
        for (int i = 1; i < v->n; i++) {
            int c = scad_value_compare(v->v[i], v->v[best]);
            if (c != 2 && (is_max ? c > 0 : c < 0)) best = i;
        }
        return scad_value_ref(v->v[best]);
    }
    if (v0.kind != SV_NUM) {
        conv_warning(ev, loc, name);
        return scad_undef();
    }
    double best = v0.u.num;
    for (int i = 1; i < a->n; i++) { /* stops at the first non-number */
        scad_value x = scad_arg_at(a, i);
        if (x.kind != SV_NUM) {
            conv_warning(ev, loc, name);
            return scad_undef();
        }
        if (is_max ? x.u.num > best : x.u.num < best) best = x.u.num;
    }
    return scad_num(best);
}

static scad_value f_norm(scad_eval *ev, const scad_argv *a, scad_loc loc, const char *name)
{
    if (a->n != 1) {
        count_warning(ev, loc, name);
        return scad_undef();
    }
    scad_value v0 = scad_arg_at(a, 0);
    if (v0.kind != SV_VEC) return scad_undef();
    double s = 0;
    const scad_vec *v = v0.u.vec;
    for (int i = 0; i < v->n; i++) {
        if (v->v[i].kind != SV_NUM) {
            scad_diag_warning(ev->d, loc, "Incorrect arguments to norm()");
            return scad_undef();
        }
        s += v->v[i].u.num * v->v[i].u.num;
    }
    return scad_num(sqrt(s));
}

/* A number's value, 0 for anything else (Value::toDouble). */
static double to_double(scad_value v)
{
    return v.kind == SV_NUM ? v.u.num : 0.0;
}

static scad_value f_cross(scad_eval *ev, const scad_argv *a, scad_loc loc, const char *name)
{
    (void)name;
    if (a->n != 2) {
        scad_diag_warning(ev->d, loc, "Invalid number of parameters for cross()");
        return scad_undef();
    }
    scad_value a0 = scad_arg_at(a, 0), a1 = scad_arg_at(a, 1);
    if (a0.kind != SV_VEC || a1.kind != SV_VEC) {
        scad_diag_warning(ev->d, loc, "Invalid type of parameters for cross()");
        return scad_undef();
    }
    const scad_vec *p = a0.u.vec, *q = a1.u.vec;
    if (p->n == 2 && q->n == 2)
        return scad_num(to_double(p->v[0]) * to_double(q->v[1]) -
                        to_double(p->v[1]) * to_double(q->v[0]));
    if (p->n != 3 || q->n != 3) {
        scad_diag_warning(ev->d, loc, "Invalid vector size of parameter for cross()");
        return scad_undef();
    }
    double x[3], y[3];
    for (int i = 0; i < 3; i++) {
        if (p->v[i].kind != SV_NUM || q->v[i].kind != SV_NUM) {
            scad_diag_warning(ev->d, loc, "Invalid value in parameter vector for cross()");
            return scad_undef();
        }
        x[i] = p->v[i].u.num;
        y[i] = q->v[i].u.num;
        if (isnan(x[i]) || isnan(y[i])) {
            scad_diag_warning(ev->d, loc, "Invalid value (NaN) in parameter vector for cross()");
            return scad_undef();
        }
        if (isinf(x[i]) || isinf(y[i])) {
            scad_diag_warning(ev->d, loc, "Invalid value (INF) in parameter vector for cross()");
            return scad_undef();
        }
    }
    scad_value r = scad_vec_new(3);
    if (r.kind != SV_VEC) return r;
    r.u.vec->v[0] = scad_num(x[1] * y[2] - x[2] * y[1]);
    r.u.vec->v[1] = scad_num(x[2] * y[0] - x[0] * y[2]);
    r.u.vec->v[2] = scad_num(x[0] * y[1] - x[1] * y[0]);
    return r;
}

static scad_value f_len(scad_eval *ev, const scad_argv *a, scad_loc loc, const char *name)
{
    if (a->n != 1) {
        count_warning(ev, loc, name);
        return scad_undef();
    }
    scad_value v = scad_arg_at(a, 0);
    if (v.kind == SV_VEC) return scad_num(v.u.vec->n);
    if (v.kind == SV_STR) return scad_num((double)v.u.str->nchars);
    conv_warning(ev, loc, name);
    return scad_undef();
}

static scad_value f_concat(scad_eval *ev, const scad_argv *a, scad_loc loc, const char *name)
{
    (void)name;
    long long total = 0;
    for (int i = 0; i < a->n; i++) {
        scad_value v = scad_arg_at(a, i);
        total += v.kind == SV_VEC ? v.u.vec->n : 1;
    }
    if (total > ev->max_list) {
        scad_eval_error(ev, loc, "list longer than %d elements (concat)", ev->max_list);
        return scad_undef();
    }
    /* each element copied is a step, as [each a, each b] counts them */
    if (scad_eval_steps(ev, (long)total, loc, "concat")) return scad_undef();
    int n = (int)total;
    scad_value r = scad_vec_new(n);
    if (r.kind != SV_VEC) {
        scad_eval_error(ev, loc, "out of memory building a vector");
        return r;
    }
    int k = 0;
    for (int i = 0; i < a->n; i++) {
        scad_value v = scad_arg_at(a, i); /* evaluated above: no evaluation here */
        if (v.kind == SV_VEC)
            for (int j = 0; j < v.u.vec->n; j++)
                r.u.vec->v[k++] = scad_value_ref(v.u.vec->v[j]);
        else
            r.u.vec->v[k++] = scad_value_ref(v);
    }
    return r;
}

static scad_value f_str(scad_eval *ev, const scad_argv *a, scad_loc loc, const char *name)
{
    (void)name;
    scad_buf b = {.limit = (size_t)ev->max_string};
    for (int i = 0; i < a->n && !b.oom && !b.too_deep; i++)
        scad_value_format(&b, scad_arg_at(a, i), 0);
    if (b.too_deep) {
        scad_eval_error(ev, loc, "a vector nested %d deep cannot be printed (str)",
                        SCAD_MAX_NESTING);
        scad_buf_free(&b);
        return scad_undef();
    }
    if (b.oom) {
        if (b.too_long)
            scad_eval_error(ev, loc, "string longer than %d bytes (str)", ev->max_string);
        else
            scad_eval_error(ev, loc, "out of memory building a string");
        scad_buf_free(&b);
        return scad_undef();
    }
    scad_value r = scad_str_new(b.p ? b.p : "", b.n);
    scad_buf_free(&b);
    return r;
}

static void put_code(scad_buf *b, double x)
{
    if (!(x >= 1 && x <= 0x10FFFF)) return;
    unsigned long cp = (unsigned long)x;
    if (cp >= 0xD800 && cp <= 0xDFFF) return;
    char o[4];
    size_t n;
    if (cp < 0x80) {
        o[0] = (char)cp;
        n = 1;
    } else if (cp < 0x800) {
        o[0] = (char)(0xC0 | (cp >> 6));
        o[1] = (char)(0x80 | (cp & 0x3F));
        n = 2;
    } else if (cp < 0x10000) {
        o[0] = (char)(0xE0 | (cp >> 12));
        o[1] = (char)(0x80 | ((cp >> 6) & 0x3F));
        o[2] = (char)(0x80 | (cp & 0x3F));
        n = 3;
    } else {
        o[0] = (char)(0xF0 | (cp >> 18));
        o[1] = (char)(0x80 | ((cp >> 12) & 0x3F));
        o[2] = (char)(0x80 | ((cp >> 6) & 0x3F));
        o[3] = (char)(0x80 | (cp & 0x3F));
        n = 4;
    }
    scad_buf_put(b, o, n);
}

static void chr_value(scad_buf *b, scad_value v)
{
    if (v.kind == SV_NUM) put_code(b, v.u.num);
    if (v.kind == SV_VEC)
        for (int i = 0; i < v.u.vec->n; i++)
            chr_value(b, v.u.vec->v[i]);
    if (v.kind == SV_RANGE) {
        double n = scad_range_count(v.u.range);
        for (double i = 0; i < n && i < 1000000; i++)
            put_code(b, scad_range_at(v.u.range, i));
    }
}

static scad_value f_chr(scad_eval *ev, const scad_argv *a, scad_loc loc, const char *name)
{
    (void)ev, (void)loc, (void)name;
    scad_buf b = {0};
    for (int i = 0; i < a->n; i++)
        chr_value(&b, scad_arg_at(a, i));
    scad_value r = scad_str_new(b.p ? b.p : "", b.oom ? 0 : b.n);
    scad_buf_free(&b);
    return r;
}

/* Whether s[0..n) is valid UTF-8 as glib's g_utf8_validate has it: no
 * overlong forms, surrogates or code points past U+10FFFF, no NUL. */
static int valid_utf8(const unsigned char *s, size_t n)
{
    for (size_t i = 0; i < n;) {
        unsigned c = s[i];
        size_t k = c < 0x80             ? 0
                   : (c & 0xE0) == 0xC0 ? 1
                   : (c & 0xF0) == 0xE0 ? 2
                   : (c & 0xF8) == 0xF0 ? 3
                                        : 9;
        if (c == 0 || k == 9 || i + k >= n) return 0;
        unsigned long cp = k == 0 ? c : c & (0x3Fu >> k);
        for (size_t j = 1; j <= k; j++) {
            if ((s[i + j] & 0xC0) != 0x80) return 0;
            cp = (cp << 6) | (s[i + j] & 0x3F);
        }
        static const unsigned long least[4] = {0, 0x80, 0x800, 0x10000};
        if (cp < least[k] || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return 0;
        i += k + 1;
    }
    return 1;
}

static scad_value f_ord(scad_eval *ev, const scad_argv *a, scad_loc loc, const char *name)
{
    (void)name;
    if (a->n == 0) return scad_undef();
    if (a->n > 1) {
        scad_diag_warning(ev->d, loc, "ord() called with %d arguments, only 1 argument expected",
                          a->n);
        return scad_undef();
    }
    scad_value v = scad_arg_at(a, 0);
    if (v.kind != SV_STR) {
        scad_buf b = {0};
        scad_value_format(&b, v, 1);
        scad_diag_warning(ev->d, loc, "ord() argument %s is not of type string", scad_buf_str(&b));
        scad_buf_free(&b);
        return scad_undef();
    }
    const unsigned char *s = (const unsigned char *)v.u.str->s;
    if (!valid_utf8(s, v.u.str->len)) {
        scad_diag_warning(ev->d, loc, "ord() argument '%s' is not a valid utf8 string", v.u.str->s);
        return scad_undef();
    }
    if (v.u.str->len == 0) return scad_undef();
    unsigned long cp = s[0];
    int extra = 0;
    if (cp >= 0xF0)
        cp &= 0x07, extra = 3;
    else if (cp >= 0xE0)
        cp &= 0x0F, extra = 2;
    else if (cp >= 0xC0)
        cp &= 0x1F, extra = 1;
    for (int i = 1; i <= extra && s[i]; i++)
        cp = (cp << 6) | (s[i] & 0x3F);
    return scad_num((double)cp);
}

static int get_num(scad_value v, double *x)
{
    if (v.kind != SV_NUM) return 0;
    *x = v.u.num;
    return 1;
}

static scad_value f_lookup(scad_eval *ev, const scad_argv *a, scad_loc loc, const char *name)
{
    double p;
    if (a->n != 2) {
        count_warning(ev, loc, name);
        return scad_undef();
    }
    if (!get_num(scad_arg_at(a, 0), &p) || !isfinite(p)) {
        /* OpenSCAD evaluates the key again to print it */
        scad_value again = scad_arg_again(a, 0);
        scad_buf b = {0};
        scad_value_format(&b, again, 1);
        scad_value_drop(again);
        scad_diag_warning(ev->d, loc, "lookup(%s, ...) first argument is not a number",
                          scad_buf_str(&b));
        scad_buf_free(&b);
        return scad_undef();
    }
    if (scad_arg_at(a, 1).kind != SV_VEC || scad_arg_at(a, 1).u.vec->n == 0) return scad_undef();
    const scad_vec *t = scad_arg_at(a, 1).u.vec;
    double low_p, low_v, high_p, high_v;
    if (t->v[0].kind != SV_VEC || t->v[0].u.vec->n < 2 || !get_num(t->v[0].u.vec->v[0], &low_p) ||
        !get_num(t->v[0].u.vec->v[1], &low_v))
        return scad_undef();
    high_p = low_p;
    high_v = low_v;
    for (int i = 1; i < t->n; i++) {
        double tp, tv;
        if (t->v[i].kind != SV_VEC || t->v[i].u.vec->n < 2 || !get_num(t->v[i].u.vec->v[0], &tp) ||
            !get_num(t->v[i].u.vec->v[1], &tv))
            continue;
        if (tp <= p && (tp > low_p || low_p > p)) {
            low_p = tp;
            low_v = tv;
        }
        if (tp >= p && (tp < high_p || high_p < p)) {
            high_p = tp;
            high_v = tv;
        }
    }
    if (p <= low_p) return scad_num(high_v);
    if (p >= high_p) return scad_num(low_v);
    double f = (p - low_p) / (high_p - low_p);
    return scad_num(high_v * f + low_v * (1 - f));
}

/* ---- rands: OpenSCAD 2021.01's one std::mt19937 for the whole evaluation
 * (seeded from the clock at the start; a seed given to rands() reseeds it,
 * so the unseeded calls after a seeded one repeat too), seeds hashed to 32
 * bits as Python hashes floats, and libstdc++'s uniform_real_distribution
 * (two 32-bit draws per double). */

typedef struct scad_mt19937 {
    uint32_t s[624];
    int i;
} scad_mt19937;

static void mt_seed(scad_mt19937 *m, uint32_t seed)
{
    m->s[0] = seed;
    for (int i = 1; i < 624; i++)
        m->s[i] = 1812433253u * (m->s[i - 1] ^ (m->s[i - 1] >> 30)) + (uint32_t)i;
    m->i = 624;
}

static uint32_t mt_next(scad_mt19937 *m)
{
    if (m->i >= 624) {
        for (int k = 0; k < 624; k++) {
            uint32_t y = (m->s[k] & 0x80000000u) | (m->s[(k + 1) % 624] & 0x7fffffffu);
            m->s[k] = m->s[(k + 397) % 624] ^ (y >> 1) ^ ((y & 1) ? 0x9908b0dfu : 0);
        }
        m->i = 0;
    }
    uint32_t y = m->s[m->i++];
    y ^= y >> 11;
    y ^= (y << 7) & 0x9d2c5680u;
    y ^= (y << 15) & 0xefc60000u;
    y ^= y >> 18;
    return y;
}

static double mt_canonical(scad_mt19937 *m)
{
    double lo = (double)mt_next(m);
    double hi = (double)mt_next(m);
    double r = (lo + hi * 4294967296.0) / 18446744073709551616.0;
    if (r >= 1.0) r = nextafter(1.0, 0.0);
    return r;
}

/* OpenSCAD's hash_floating_point: CPython's hash of a float with a 31-bit
 * modulus (so whole seeds hash to themselves), in 32-bit unsigned
 * arithmetic as it is there, without CPython's final -1 -> -2 step. */
static uint32_t seed_hash(double v)
{
    const uint32_t mod = (1u << 31) - 1;
    if (isnan(v)) return 0;
    if (isinf(v)) return v > 0 ? 314159u : 0u - 314159u;
    int e;
    double m = frexp(v, &e);
    uint32_t sign = 1;
    if (m < 0) {
        sign = 0u - 1u;
        m = -m;
    }
    uint32_t x = 0;
    while (m != 0) { /* 28 bits at a time */
        x = ((x << 28) & mod) | x >> (31 - 28);
        m *= 268435456.0;
        e -= 28;
        uint32_t y = (uint32_t)m;
        m -= y;
        x += y;
        if (x >= mod) x -= mod;
    }
    e = e >= 0 ? e % 31 : 31 - 1 - ((-1 - e) % 31);
    x = ((x << e) & mod) | x >> (31 - e);
    return x * sign;
}

/* The evaluation's engine, made (and seeded from the clock) on first use. */
static scad_mt19937 *engine(scad_eval *ev)
{
    if (!ev->rng) {
        ev->rng = scad_arena_alloc(ev->arena, sizeof *ev->rng);
        if (ev->rng) mt_seed(ev->rng, (uint32_t)ev->rand_seed);
    }
    return ev->rng;
}

/* "WARNING: <line>" without a location, as OpenSCAD's follow-up lines. */
static void bare_warning(scad_eval *ev, const char *fmt, double x)
{
    char line[512];
    int n = snprintf(line, sizeof line, "WARNING: ");
    snprintf(line + n, sizeof line - (size_t)n, fmt, x);
    scad_diag_line(ev->d, RAYSCAD_MSG_WARNING, line);
}

/* In OpenSCAD 2021.01's order: a wrong count warns; a non-number argument
 * gives undef silently, checked one at a time between the range warnings. */
static scad_value f_rands(scad_eval *ev, const scad_argv *a, scad_loc loc, const char *name)
{
    if (a->n < 3 || a->n > 4) {
        count_warning(ev, loc, name);
        return scad_undef();
    }
    if (scad_arg_at(a, 0).kind != SV_NUM) return scad_undef();
    double lo = scad_arg_at(a, 0).u.num;
    if (!isfinite(lo)) {
        scad_diag_warning(ev->d, loc, "rands() range min cannot be infinite");
        lo = -DBL_MAX / 2;
        bare_warning(ev, "resetting to %f", lo);
    }
    if (scad_arg_at(a, 1).kind != SV_NUM) return scad_undef();
    double hi = scad_arg_at(a, 1).u.num;
    if (!isfinite(hi)) {
        scad_diag_warning(ev->d, loc, "rands() range max cannot be infinite");
        hi = DBL_MAX / 2;
        bare_warning(ev, "resetting to %f", hi);
    }
    if (hi < lo) {
        double t = lo;
        lo = hi;
        hi = t;
    }
    if (scad_arg_at(a, 2).kind != SV_NUM) return scad_undef();
    double count = fabs(scad_arg_at(a, 2).u.num);
    if (!isfinite(count)) {
        scad_diag_warning(ev->d, loc, "rands() cannot create an infinite number of results");
        scad_diag_line(ev->d, RAYSCAD_MSG_WARNING, "WARNING: resetting number of results to 1");
        count = 1;
    }
    if (a->n == 4 && scad_arg_at(a, 3).kind != SV_NUM) return scad_undef();
    /* every value is a step of work: a count past the limits stops there */
    if (count > ev->max_list ||
        scad_eval_steps(ev, (long)count, loc, "the values rands() makes") != 0) {
        if (!ev->aborted) scad_eval_error(ev, loc, "rands() cannot make %.0f values", floor(count));
        return scad_undef();
    }
    scad_mt19937 *m = engine(ev);
    if (!m) {
        scad_eval_error(ev, loc, "out of memory");
        return scad_undef();
    }
    if (a->n == 4) mt_seed(m, seed_hash(scad_arg_at(a, 3).u.num));
    int n = (int)count;
    scad_value r = scad_vec_new(n);
    if (r.kind == SV_VEC)
        for (int i = 0; i < n; i++)
            r.u.vec->v[i] = scad_num(lo >= hi ? lo : mt_canonical(m) * (hi - lo) + lo);
    return r;
}

/* search(match, in, num_returns_per_match = 1, index_col_num = 0) */
/* OpenSCAD 2021.01's test: with index_col_num 0 the whole entry may match
 * too (so a list matches a list), else column col of a list entry. */
static int search_eq(scad_value item, scad_value match, int col)
{
    if (col == 0 && scad_value_equal(item, match)) return 1;
    return item.kind == SV_VEC && col >= 0 && col < item.u.vec->n &&
           scad_value_equal(item.u.vec->v[col], match);
}

static scad_value search_one(scad_value match, scad_value in, int nret, int col, int as_list)
{
    int n = in.kind == SV_VEC ? in.u.vec->n : 0;
    scad_value *hits = malloc(sizeof *hits * (size_t)(n ? n : 1));
    int k = 0;
    for (int i = 0; hits && i < n; i++) {
        if (search_eq(in.u.vec->v[i], match, col)) {
            hits[k++] = scad_num(i);
            if (nret > 0 && k >= nret) break;
        }
    }
    scad_value r;
    if (!as_list && k == 1 && nret == 1) {
        r = hits[0];
    } else {
        r = scad_vec_new(k);
        if (r.kind == SV_VEC)
            for (int i = 0; i < k; i++)
                r.u.vec->v[i] = hits[i];
    }
    free(hits);
    return r;
}

static scad_value f_search(scad_eval *ev, const scad_argv *a, scad_loc loc, const char *name)
{
    if (a->n < 2) {
        count_warning(ev, loc, name);
        return scad_undef();
    }
    scad_value match = scad_arg_at(a, 0), in = scad_arg_at(a, 1);
    double d;
    /* NaN and out-of-range counts clamp (a cast would be undefined) */
    int nret =
        a->n > 2 && get_num(scad_arg_at(a, 2), &d) ? (int)fmax(fmin(d, INT_MAX), INT_MIN + 1.0) : 1;
    int col =
        a->n > 3 && get_num(scad_arg_at(a, 3), &d) ? (int)fmax(fmin(d, INT_MAX), INT_MIN + 1.0) : 0;
    scad_value hay = scad_value_ref(in);
    if (in.kind == SV_STR) {
        /* characters of the string, as a vector of one-character strings */
        scad_value_drop(hay);
        int n = (int)in.u.str->nchars;
        hay = scad_vec_new(n);
        for (int i = 0; hay.kind == SV_VEC && i < n; i++) {
            const char *s = in.u.str->s;
            size_t pos = 0;
            for (int c = 0; c < i; c++)
                pos += scad_utf8_char_len(s, pos, in.u.str->len);
            hay.u.vec->v[i] = scad_str_new(s + pos, scad_utf8_char_len(s, pos, in.u.str->len));
        }
    }
    scad_value r;
    if (match.kind == SV_STR && in.kind == SV_VEC) {
        for (int i = 0; i < in.u.vec->n; i++) {
            scad_value e = in.u.vec->v[i];
            if (e.kind != SV_VEC || e.u.vec->n <= col) {
                scad_buf b = {0};
                scad_value_format(&b, e, 1);
                scad_diag_warning(ev->d, loc,
                                  "Invalid entry in search vector at index %d, required number of "
                                  "values in the entry: %d. Invalid entry: %s",
                                  i, col + 1, scad_buf_str(&b));
                scad_buf_free(&b);
                scad_value_drop(hay);
                return scad_vec_new(0);
            }
        }
    }
    if (match.kind == SV_NUM) {
        r = search_one(match, hay, nret, col, 1);
    } else if (match.kind == SV_STR || match.kind == SV_VEC) {
        int n = match.kind == SV_STR ? (int)match.u.str->nchars : match.u.vec->n;
        r = scad_vec_new(n);
        const char *s = match.kind == SV_STR ? match.u.str->s : NULL;
        size_t pos = 0;
        int k = 0;
        for (int i = 0; r.kind == SV_VEC && i < n; i++) {
            scad_value m;
            if (s) {
                size_t len = scad_utf8_char_len(s, pos, match.u.str->len);
                m = scad_str_new(s + pos, len);
                pos += len;
            } else {
                m = scad_value_ref(match.u.vec->v[i]);
            }
            scad_value hit = search_one(m, hay, nret, col, 0);
            if (s && in.kind != SV_STR && hit.kind == SV_VEC && hit.u.vec->n == 0) {
                scad_buf b = {0};
                scad_value_format(&b, m, 1);
                scad_diag_warning(ev->d, loc, "search term not found: %s", scad_buf_str(&b));
                scad_buf_free(&b);
            }
            scad_value_drop(m);
            if (nret == 1 && hit.kind == SV_VEC && hit.u.vec->n == 0 && s) {
                scad_value_drop(hit); /* a character not found is left out */
                continue;
            }
            r.u.vec->v[k++] = hit;
        }
        if (r.kind == SV_VEC) r.u.vec->n = k;
    } else {
        r = scad_undef();
    }
    scad_value_drop(hay);
    return r;
}

static scad_value f_is(scad_eval *ev, const scad_argv *a, scad_loc loc, const char *name)
{
    if (a->n != 1) {
        count_warning(ev, loc, name);
        return scad_undef();
    }
    scad_value v = scad_arg_at(a, 0);
    const char *t = name + 3;
    if (!strcmp(t, "undef")) return scad_bool(v.kind == SV_UNDEF);
    if (!strcmp(t, "num")) return scad_bool(v.kind == SV_NUM && !isnan(v.u.num));
    if (!strcmp(t, "bool")) return scad_bool(v.kind == SV_BOOL);
    if (!strcmp(t, "string")) return scad_bool(v.kind == SV_STR);
    if (!strcmp(t, "list")) return scad_bool(v.kind == SV_VEC);
    return scad_bool(v.kind == SV_FUNC);
}

/* parent_module(n): the name of the n-th user module up the instantiation
 * stack (1, the default, is the caller of the current one). */
static scad_value f_parent_module(scad_eval *ev, const scad_argv *a, scad_loc loc, const char *name)
{
    double d = 1;
    if (a->n == 1) {
        if (scad_arg_at(a, 0).kind != SV_NUM) return scad_undef();
        d = scad_arg_at(a, 0).u.num;
    } else if (a->n > 1) {
        count_warning(ev, loc, name);
        return scad_undef();
    }
    int depth = ev->module_depth < ev->module_names_cap ? ev->module_depth : ev->module_names_cap;
    double n = trunc(d);
    if (n < 0) {
        scad_diag_warning(ev->d, loc, "Negative parent module index (%d) not allowed", (int)n);
        return scad_undef();
    }
    if (!(n < depth)) {
        scad_diag_warning(ev->d, loc,
                          "Parent module index (%d) greater than the number of modules on the "
                          "stack",
                          n < 2147483647.0 ? (int)n : 2147483647);
        return scad_undef();
    }
    const char *m = ev->module_names[depth - 1 - (int)n];
    return scad_str_new(m, strlen(m));
}

/* version() is [2021, 1, 0]; version_num() 20210100, or of a given
 * [y, m, d] (or [y, m]) y * 10000 + m * 100 + d. */
static scad_value f_version(scad_eval *ev, const scad_argv *a, scad_loc loc, const char *name)
{
    (void)ev, (void)loc;
    double ymd[3] = {2021, 1, 0};
    if (!strcmp(name, "version_num")) {
        if (a->n > 0) {
            scad_value v = scad_arg_at(a, 0);
            if (v.kind != SV_VEC || v.u.vec->n < 2 || v.u.vec->n > 3) return scad_undef();
            ymd[2] = 0;
            for (int i = 0; i < v.u.vec->n; i++) {
                if (v.u.vec->v[i].kind != SV_NUM) return scad_undef();
                ymd[i] = v.u.vec->v[i].u.num;
            }
        }
        return scad_num(ymd[0] * 10000 + ymd[1] * 100 + ymd[2]);
    }
    scad_value r = scad_vec_new(3);
    if (r.kind == SV_VEC)
        for (int i = 0; i < 3; i++)
            r.u.vec->v[i] = scad_num(ymd[i]);
    return r;
}

const scad_function_def scad_math_functions[] = {
    {"abs", "x", f_unary},
    {"acos", "x", f_unary},
    {"asin", "x", f_unary},
    {"atan", "x", f_unary},
    {"atan2", "y, x", f_atan2},
    {"ceil", "x", f_unary},
    {"chr", "code, …", f_chr},
    {"concat", "list, …", f_concat},
    {"cos", "degrees", f_unary},
    {"cross", "a, b", f_cross},
    {"exp", "x", f_unary},
    {"floor", "x", f_unary},
    {"is_bool", "v", f_is},
    {"is_function", "v", f_is},
    {"is_list", "v", f_is},
    {"is_num", "v", f_is},
    {"is_string", "v", f_is},
    {"is_undef", "v", f_is},
    {"len", "list or string", f_len},
    {"ln", "x", f_unary},
    {"log", "[base,] x", f_log},
    {"lookup", "key, table", f_lookup},
    {"max", "values or list", f_minmax},
    {"min", "values or list", f_minmax},
    {"norm", "vector", f_norm},
    {"ord", "string", f_ord},
    {"parent_module", "[n]", f_parent_module},
    {"pow", "base, exponent", f_pow},
    {"rands", "min, max, count[, seed]", f_rands},
    {"round", "x", f_unary},
    {"search", "match, in[, num_returns[, index_col]]", f_search},
    {"sign", "x", f_unary},
    {"sin", "degrees", f_unary},
    {"sqrt", "x", f_unary},
    {"str", "value, …", f_str},
    {"tan", "degrees", f_unary},
    {"version", "", f_version},
    {"version_num", "", f_version},
    {NULL, NULL, NULL},
};
