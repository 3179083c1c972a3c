/*
 * value.c — OpenSCAD values: reference-counted heap parts, truth, equality,
 * and the text forms echo() and str() print.
 *
 * A heap value (string, vector, range, function literal) starts with one
 * reference, held by whoever built it; it is freed when the last reference
 * is dropped, after dropping the references its elements hold.  Numbers are
 * printed as OpenSCAD 2021.01 prints them (double-conversion, 6 significant
 * digits, rounding half up on the exact binary value).
 */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <stdint.h>
#include <string.h>

#include "value.h"

size_t scad_utf8_char_len(const char *s, size_t pos, size_t len)
{
    unsigned char c = (unsigned char)s[pos];
    size_t k = c < 0xC0   ? 1
               : c < 0xE0 ? 2
               : c < 0xF0 ? 3
               : c < 0xF8 ? 4
               : c < 0xFC ? 5
               : c < 0xFE ? 6
                          : 1;
    return pos + k > len ? len - pos : k;
}

/* Characters of s[0 .. len), as scad_utf8_char_len steps through them;
 * eight bytes at a time where all eight are ASCII (a string built up one
 * character at a time is counted again at each step: the corpus's
 * tail-recursion-tests.scad spent nine tenths of its time here). */
static size_t utf8_count(const char *s, size_t len)
{
    size_t n = 0, i = 0;
    while (i < len) {
        uint64_t w;
        if (len - i >= 8 && (memcpy(&w, s + i, 8), (w & 0x8080808080808080ULL) == 0)) {
            i += 8;
            n += 8;
            continue;
        }
        i += scad_utf8_char_len(s, i, len);
        n++;
    }
    return n;
}

scad_value scad_str_new(const char *s, size_t len)
{
    scad_str *p = malloc(sizeof *p + len + 1);
    if (!p) return scad_undef();
    p->refs = 1;
    p->len = len;
    memcpy(p->s, s, len);
    p->s[len] = 0;
    p->nchars = utf8_count(s, len);
    scad_value v;
    v.kind = SV_STR;
    v.u.str = p;
    return v;
}

scad_value scad_vec_new(int n)
{
    if (n > SCAD_MAX_LIST) return scad_undef();
    scad_vec *p = malloc(sizeof *p + sizeof(scad_value) * (size_t)(n > 0 ? n : 0));
    if (!p) return scad_undef();
    p->refs = 1;
    p->n = n;
    for (int i = 0; i < n; i++)
        p->v[i] = scad_undef();
    scad_value v;
    v.kind = SV_VEC;
    v.u.vec = p;
    return v;
}

scad_value scad_range_new(double begin, double step, double end)
{
    scad_range *p = malloc(sizeof *p);
    if (!p) return scad_undef();
    p->refs = 1;
    p->begin = begin;
    p->step = step;
    p->end = end;
    scad_value v;
    v.kind = SV_RANGE;
    v.u.range = p;
    return v;
}

scad_value scad_func_new(const scad_expr *lit, scad_env *env)
{
    scad_func *p = malloc(sizeof *p);
    if (!p) return scad_undef();
    p->refs = 1;
    p->lit = lit;
    p->env = env;
    scad_value v;
    v.kind = SV_FUNC;
    v.u.func = p;
    return v;
}

scad_value scad_value_ref(scad_value v)
{
    switch (v.kind) {
    case SV_STR:
        v.u.str->refs++;
        break;
    case SV_VEC:
        v.u.vec->refs++;
        break;
    case SV_RANGE:
        v.u.range->refs++;
        break;
    case SV_FUNC:
        v.u.func->refs++;
        break;
    default:
        break;
    }
    return v;
}

void scad_value_drop(scad_value v)
{
    switch (v.kind) {
    case SV_STR:
        if (--v.u.str->refs == 0) free(v.u.str);
        break;
    case SV_VEC:
        if (--v.u.vec->refs == 0) {
            /* Drop nested vectors iteratively along the last element, so
             * that a long chain of [x, [y, [z, …]]] does not recurse deeply. */
            scad_vec *p = v.u.vec;
            while (p) {
                scad_vec *nextp = NULL;
                for (int i = 0; i < p->n; i++) {
                    scad_value e = p->v[i];
                    if (e.kind == SV_VEC && !nextp && e.u.vec->refs == 1)
                        nextp = e.u.vec;
                    else
                        scad_value_drop(e);
                }
                free(p);
                p = nextp;
            }
        }
        break;
    case SV_RANGE:
        if (--v.u.range->refs == 0) free(v.u.range);
        break;
    case SV_FUNC:
        if (--v.u.func->refs == 0) free(v.u.func);
        break;
    default:
        break;
    }
}

int scad_value_truthy(scad_value v)
{
    switch (v.kind) {
    case SV_UNDEF:
        return 0;
    case SV_BOOL:
        return v.u.b;
    case SV_NUM:
        return v.u.num != 0; /* NaN is true, as in OpenSCAD 2021.01 */
    case SV_STR:
        return v.u.str->len > 0;
    case SV_VEC:
        return v.u.vec->n > 0;
    case SV_RANGE:
        return 1;
    case SV_FUNC:
        return 1;
    }
    return 0;
}

int scad_value_equal(scad_value a, scad_value b)
{
    if (a.kind != b.kind) return 0;
    switch (a.kind) {
    case SV_UNDEF:
        return 1;
    case SV_BOOL:
        return a.u.b == b.u.b;
    case SV_NUM:
        return a.u.num == b.u.num;
    case SV_STR:
        return a.u.str->len == b.u.str->len && memcmp(a.u.str->s, b.u.str->s, a.u.str->len) == 0;
    case SV_VEC:
        if (a.u.vec->n != b.u.vec->n) return 0;
        for (int i = 0; i < a.u.vec->n; i++)
            if (!scad_value_equal(a.u.vec->v[i], b.u.vec->v[i])) return 0;
        return 1;
    case SV_RANGE: {
        /* OpenSCAD 2021.01's RangeType ==: empty ranges are equal, others
         * by begin, step and number of values (so [0:1:3] == [0:1:3.5]) */
        double n = scad_range_steps(a.u.range), m = scad_range_steps(b.u.range);
        if (n == 0 || m == 0) return n == m;
        return a.u.range->begin == b.u.range->begin && a.u.range->step == b.u.range->step && n == m;
    }
    case SV_FUNC:
        return a.u.func == b.u.func;
    }
    return 0;
}

int scad_value_compare(scad_value a, scad_value b)
{
    if (a.kind != b.kind) return 2;
    switch (a.kind) {
    case SV_NUM:
        if (a.u.num < b.u.num) return -1;
        if (a.u.num > b.u.num) return 1;
        return a.u.num == b.u.num ? 0 : 2;
    case SV_BOOL:
        return (a.u.b > b.u.b) - (a.u.b < b.u.b);
    case SV_STR: {
        int c = strcmp(a.u.str->s, b.u.str->s);
        return (c > 0) - (c < 0);
    }
    case SV_VEC: {
        const scad_vec *A = a.u.vec, *B = b.u.vec;
        for (int i = 0; i < A->n && i < B->n; i++) {
            int c = scad_value_compare(A->v[i], B->v[i]);
            if (c != 0) return c;
        }
        return (A->n > B->n) - (A->n < B->n);
    }
    case SV_RANGE: {
        /* OpenSCAD 2021.01's RangeType order: empty first, then begin,
         * step and number of values */
        const scad_range *A = a.u.range, *B = b.u.range;
        double n = scad_range_steps(A), m = scad_range_steps(B);
        if (n == 0 || m == 0) return (n != 0) - (m != 0);
        if (A->begin != B->begin) return A->begin < B->begin ? -1 : 1;
        if (A->step != B->step) return A->step < B->step ? -1 : 1;
        return (n > m) - (n < m);
    }
    default:
        return 2;
    }
}

const char *scad_value_type_name(scad_value v)
{
    static const char *names[] = {"undefined", "bool",  "number",  "string",
                                  "vector",    "range", "function"};
    return names[v.kind];
}

/* Number of values of a range as OpenSCAD counts them: the quotient is
 * nudged up by one ulp so that [0:0.1:0.3] has 4 values; a zero step or an
 * infinite end gives UINT32_MAX (which the loop limit then refuses). */
double scad_range_steps(const scad_range *r)
{
    if (isnan(r->begin) || isnan(r->end) || isnan(r->step)) return 0;
    if (r->step < 0 ? r->begin < r->end : r->begin > r->end) return 0;
    if (r->begin == r->end || isinf(r->step)) return 1;
    if (isinf(r->begin) || isinf(r->end) || r->step == 0) return 4294967295.0;
    double q = floor(nextafter((r->end - r->begin) / r->step, INFINITY));
    if (q >= 4294967295.0) return 4294967295.0;
    return q + 1;
}

double scad_range_at(const scad_range *r, double i)
{
    return i == 0 ? r->begin : r->begin + i * r->step;
}

double scad_range_count(const scad_range *r)
{
    if (!isfinite(r->begin) || !isfinite(r->step) || !isfinite(r->end)) return -1;
    if (r->step == 0) return 0;
    if ((r->step > 0 && r->begin > r->end) || (r->step < 0 && r->begin < r->end)) return 0;
    return floor((r->end - r->begin) / r->step) + 1;
}

/* ---- text ----------------------------------------------------------------- */

void scad_buf_put(scad_buf *b, const char *s, size_t n)
{
    if (b->oom) return;
    size_t limit = b->limit ? b->limit : SCAD_MAX_STRING;
    if (n > limit || b->n + n > limit) {
        b->oom = b->too_long = 1;
        return;
    }
    if (b->n + n + 1 > b->cap) {
        size_t cap = b->cap ? b->cap : 64;
        while (cap < b->n + n + 1)
            cap *= 2;
        char *p = realloc(b->p, cap);
        if (!p) {
            b->oom = 1;
            return;
        }
        b->p = p;
        b->cap = cap;
    }
    memcpy(b->p + b->n, s, n);
    b->n += n;
    b->p[b->n] = 0;
}

void scad_buf_puts(scad_buf *b, const char *s)
{
    scad_buf_put(b, s, strlen(s));
}

void scad_buf_printf(scad_buf *b, const char *fmt, ...)
{
    char tmp[512];
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(tmp, sizeof tmp, fmt, ap);
    va_end(ap);
    if (n < 0) return;
    scad_buf_put(b, tmp, (size_t)n < sizeof tmp ? (size_t)n : sizeof tmp - 1);
}

void scad_buf_free(scad_buf *b)
{
    free(b->p);
    b->p = NULL;
    b->n = b->cap = 0;
}

const char *scad_buf_str(scad_buf *b)
{
    return b->p && !b->oom ? b->p : "";
}

/* Six significant digits, rounded half up on the exact binary value (as
 * double-conversion's precision mode does; printf would round half to even
 * and print 1234565 as 1.23456e+06 where OpenSCAD prints 1.23457e+6).
 * Decimal notation for exponents -5 … 5, otherwise d.ddddde±x; trailing
 * zeros of the fraction are dropped. */
void scad_format_number(double d, char *buf)
{
    if (isnan(d)) {
        strcpy(buf, "nan");
        return;
    }
    if (isinf(d)) {
        strcpy(buf, d < 0 ? "-inf" : "inf");
        return;
    }
    if (d == 0) {
        strcpy(buf, "0");
        return;
    }
    /* Exact enough: 40 digits cover every tie that matters at 6 digits. */
    char raw[64];
    snprintf(raw, sizeof raw, "%.40e", fabs(d));
    char digits[8];
    int k = 0;
    digits[k++] = raw[0];
    for (int i = 2; k < 6; i++)
        digits[k++] = raw[i];
    int exp10 = atoi(strchr(raw, 'e') + 1);
    if (raw[7] >= '5') { /* half up: look only at the 7th digit */
        int i = 5;
        while (i >= 0 && digits[i] == '9')
            digits[i--] = '0';
        if (i < 0) {
            memmove(digits + 1, digits, 5);
            digits[0] = '1';
            exp10++;
        } else {
            digits[i]++;
        }
    }
    int nd = 6;
    while (nd > 1 && digits[nd - 1] == '0')
        nd--;
    char *o = buf;
    if (d < 0) *o++ = '-';
    if (exp10 < -5 || exp10 >= 6) {
        *o++ = digits[0];
        if (nd > 1) {
            *o++ = '.';
            for (int i = 1; i < nd; i++)
                *o++ = digits[i];
        }
        sprintf(o, "e%c%d", exp10 < 0 ? '-' : '+', abs(exp10));
        return;
    }
    if (exp10 < 0) {
        *o++ = '0';
        *o++ = '.';
        for (int i = -1; i > exp10; i--)
            *o++ = '0';
        for (int i = 0; i < nd; i++)
            *o++ = digits[i];
    } else {
        for (int i = 0; i <= exp10; i++)
            *o++ = i < nd ? digits[i] : '0';
        if (nd > exp10 + 1) {
            *o++ = '.';
            for (int i = exp10 + 1; i < nd; i++)
                *o++ = digits[i];
        }
    }
    *o = 0;
}

void scad_quote_escaped(scad_buf *b, const char *s, size_t n)
{
    scad_buf_put(b, "\"", 1);
    size_t from = 0;
    for (size_t i = 0; i < n; i++) {
        const char *esc = s[i] == '\t'   ? "\\t"
                          : s[i] == '\n' ? "\\n"
                          : s[i] == '\r' ? "\\r"
                          : s[i] == '"'  ? "\\\""
                          : s[i] == '\\' ? "\\\\"
                                         : NULL;
        if (!esc) continue;
        scad_buf_put(b, s + from, i - from);
        scad_buf_puts(b, esc);
        from = i + 1;
    }
    scad_buf_put(b, s + from, n - from);
    scad_buf_put(b, "\"", 1);
}

static void put_number(scad_buf *b, double d)
{
    char tmp[32];
    scad_format_number(d, tmp);
    scad_buf_puts(b, tmp);
}

static void format_params(scad_buf *b, const scad_args *a)
{
    for (int i = 0; i < a->n; i++) {
        if (i) scad_buf_puts(b, ", ");
        if (a->v[i].name) scad_buf_puts(b, a->v[i].name);
        if (a->v[i].name && a->v[i].value) scad_buf_puts(b, " = ");
        if (a->v[i].value) scad_expr_format(b, a->v[i].value);
    }
}

const char *scad_op_text(int op, char buf[2])
{
    switch (op) {
    case TK_LE:
        return "<=";
    case TK_GE:
        return ">=";
    case TK_EQ:
        return "==";
    case TK_NE:
        return "!=";
    case TK_AND:
        return "&&";
    case TK_OR:
        return "||";
    default:
        buf[0] = (char)op;
        buf[1] = 0;
        return buf;
    }
}

void scad_expr_format(scad_buf *b, const scad_expr *e)
{
    char one[2];
    switch (e->kind) {
    case EX_NUMBER:
        put_number(b, e->num);
        break;
    case EX_STRING:
        scad_quote_escaped(b, e->str, e->len);
        break;
    case EX_BOOL:
        scad_buf_puts(b, e->num ? "true" : "false");
        break;
    case EX_UNDEF:
        scad_buf_puts(b, "undef");
        break;
    case EX_VAR:
        scad_buf_puts(b, e->str);
        break;
    case EX_RANGE:
        scad_buf_puts(b, "[");
        scad_expr_format(b, e->a[0]);
        if (e->a[1]) {
            scad_buf_puts(b, " : ");
            scad_expr_format(b, e->a[1]);
        }
        scad_buf_puts(b, " : ");
        scad_expr_format(b, e->a[2]);
        scad_buf_puts(b, "]");
        break;
    case EX_VECTOR:
        scad_buf_puts(b, "[");
        for (int i = 0; i < e->n; i++) {
            if (i) scad_buf_puts(b, ", ");
            scad_expr_format(b, e->list[i]);
        }
        scad_buf_puts(b, "]");
        break;
    case EX_UNARY:
        /* 2021.01's parser drops a unary plus: +x is x */
        if (e->op != '+') scad_buf_puts(b, scad_op_text(e->op, one));
        scad_expr_format(b, e->a[0]);
        break;
    case EX_BINARY:
        scad_buf_puts(b, "(");
        scad_expr_format(b, e->a[0]);
        scad_buf_printf(b, " %s ", scad_op_text(e->op, one));
        scad_expr_format(b, e->a[1]);
        scad_buf_puts(b, ")");
        break;
    case EX_TERNARY:
        scad_buf_puts(b, "(");
        scad_expr_format(b, e->a[0]);
        scad_buf_puts(b, " ? ");
        scad_expr_format(b, e->a[1]);
        scad_buf_puts(b, " : ");
        scad_expr_format(b, e->a[2]);
        scad_buf_puts(b, ")");
        break;
    case EX_CALL:
        /* a callee other than a name is printed in parens, as 2021.01 */
        if (e->a[0]->kind != EX_VAR) scad_buf_puts(b, "(");
        scad_expr_format(b, e->a[0]);
        if (e->a[0]->kind != EX_VAR) scad_buf_puts(b, ")");
        scad_buf_puts(b, "(");
        format_params(b, &e->args);
        scad_buf_puts(b, ")");
        break;
    case EX_INDEX:
        scad_expr_format(b, e->a[0]);
        scad_buf_puts(b, "[");
        scad_expr_format(b, e->a[1]);
        scad_buf_puts(b, "]");
        break;
    case EX_MEMBER:
        scad_expr_format(b, e->a[0]);
        scad_buf_printf(b, ".%s", e->str);
        break;
    case EX_LET:
    case LC_LET:
        /* a comprehension's let (LcLet) has its body in parens */
        scad_buf_puts(b, "let(");
        format_params(b, &e->args);
        scad_buf_puts(b, e->kind == LC_LET ? ") (" : ") ");
        scad_expr_format(b, e->a[0]);
        if (e->kind == LC_LET) scad_buf_puts(b, ")");
        break;
    case EX_ASSERT:
    case EX_ECHO:
        scad_buf_puts(b, e->kind == EX_ASSERT ? "assert(" : "echo(");
        format_params(b, &e->args);
        scad_buf_puts(b, ")");
        if (e->a[0]) {
            scad_buf_puts(b, " ");
            scad_expr_format(b, e->a[0]);
        }
        break;
    case EX_FUNCLIT:
        scad_buf_puts(b, "function(");
        format_params(b, &e->args);
        scad_buf_puts(b, ") ");
        scad_expr_format(b, e->a[0]);
        break;
    case LC_FOR:
        /* 2021.01 nests a for over several variables, each body in parens */
        for (int i = 0; i < e->args.n; i++) {
            scad_buf_puts(b, "for(");
            if (e->args.v[i].name) scad_buf_printf(b, "%s = ", e->args.v[i].name);
            if (e->args.v[i].value) scad_expr_format(b, e->args.v[i].value);
            scad_buf_puts(b, ") (");
        }
        scad_expr_format(b, e->a[0]);
        for (int i = 0; i < e->args.n; i++)
            scad_buf_puts(b, ")");
        break;
    case LC_CFOR:
        scad_buf_puts(b, "for(");
        format_params(b, &e->args);
        scad_buf_puts(b, ";");
        scad_expr_format(b, e->a[1]);
        scad_buf_puts(b, ";");
        format_params(b, &e->args2);
        scad_buf_puts(b, ") ");
        scad_expr_format(b, e->a[0]);
        break;
    case LC_IF:
        scad_buf_puts(b, "if(");
        scad_expr_format(b, e->a[1]);
        scad_buf_puts(b, ") (");
        scad_expr_format(b, e->a[0]);
        scad_buf_puts(b, ")");
        if (e->a[2]) {
            scad_buf_puts(b, " else (");
            scad_expr_format(b, e->a[2]);
            scad_buf_puts(b, ")");
        }
        break;
    case LC_EACH:
        scad_buf_puts(b, "each (");
        scad_expr_format(b, e->a[0]);
        scad_buf_puts(b, ")");
        break;
    }
}

static void format_at(scad_buf *b, scad_value v, int quote_strings, int depth)
{
    switch (v.kind) {
    case SV_UNDEF:
        scad_buf_puts(b, "undef");
        break;
    case SV_BOOL:
        scad_buf_puts(b, v.u.b ? "true" : "false");
        break;
    case SV_NUM:
        put_number(b, v.u.num);
        break;
    case SV_STR:
        if (quote_strings) scad_buf_puts(b, "\"");
        scad_buf_put(b, v.u.str->s, v.u.str->len);
        if (quote_strings) scad_buf_puts(b, "\"");
        break;
    case SV_VEC:
        if (depth >= SCAD_MAX_NESTING) {
            b->too_deep = 1;
            return;
        }
        scad_buf_puts(b, "[");
        for (int i = 0; i < v.u.vec->n && !b->too_deep; i++) {
            if (i) scad_buf_puts(b, ", ");
            format_at(b, v.u.vec->v[i], 1, depth + 1);
        }
        scad_buf_puts(b, "]");
        break;
    case SV_RANGE:
        scad_buf_puts(b, "[");
        put_number(b, v.u.range->begin);
        scad_buf_puts(b, " : ");
        put_number(b, v.u.range->step);
        scad_buf_puts(b, " : ");
        put_number(b, v.u.range->end);
        scad_buf_puts(b, "]");
        break;
    case SV_FUNC:
        scad_expr_format(b, v.u.func->lit);
        break;
    }
}

void scad_value_format(scad_buf *b, scad_value v, int quote_strings)
{
    format_at(b, v, quote_strings, 0);
}
