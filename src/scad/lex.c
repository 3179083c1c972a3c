/*
 * lex.c — the OpenSCAD tokeniser.
 *
 * One pass over the source text turns it into an array of scad_token,
 * ending with TK_EOF, grown by realloc (the caller frees it once the file
 * is parsed: the syntax tree keeps none of it; token texts are in the
 * arena).  Each token records the
 * line and column of its first character; columns count bytes from 1.
 * Like flex in OpenSCAD's lexer.l the longest match wins, so "2x" is an
 * identifier and "2e3" a number.  Errors (an unterminated string or comment,
 * a stray character) are reported and lexing goes on.
 */
#include <ctype.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "ast.h"

typedef struct lexer {
    scad_arena *a;
    scad_diag *d;
    scad_names *names;
    const char *file;
    const char *p;
    int line, col;
    scad_token *v;
    int n, cap;
    int failed; /* stop: out of memory, or an unterminated string */
    int oom;    /* out of memory: the tokens are incomplete */
} lexer;

static void advance(lexer *L, size_t k)
{
    while (k-- && *L->p) {
        if (*L->p == '\n') {
            L->line++;
            L->col = 1;
        } else {
            L->col++;
        }
        L->p++;
    }
}

/* Past k bytes without counting their lines, as openscad 2021.01 does
 * inside include <…> and use <…>: later lines are numbered that much
 * lower in its messages, and so in ours. */
static void advance_uncounted(lexer *L, size_t k)
{
    while (k-- && *L->p) {
        L->col++;
        L->p++;
    }
}

/* The line openscad 2021.01 reports an error at the end of the file on:
 * it lexes the file with "\n\x03\n" appended. */
static int eof_line(const lexer *L)
{
    return L->line + 2;
}

static void out_of_memory(lexer *L)
{
    L->oom = L->failed = 1;
}

/* A new token at the end of the array; NULL when out of memory (recorded). */
static scad_token *push(lexer *L, scad_tok_kind kind, scad_loc loc)
{
    if (L->n == L->cap) {
        int cap = L->cap ? L->cap * 2 : 256;
        scad_token *v = L->cap < INT_MAX / 2 ? realloc(L->v, sizeof *v * (size_t)cap) : NULL;
        if (!v) {
            out_of_memory(L);
            return NULL;
        }
        L->v = v;
        L->cap = cap;
    }
    scad_token *t = &L->v[L->n++];
    memset(t, 0, sizeof *t);
    t->kind = kind;
    t->loc = loc;
    return t;
}

static int is_idch(int c)
{
    return isalnum(c) || c == '_';
}

static size_t number_length(const char *s)
{
    size_t i = 0, digits = 0;
    while (isdigit((unsigned char)s[i]))
        i++, digits++;
    if (s[i] == '.') {
        size_t j = i + 1, frac = 0;
        while (isdigit((unsigned char)s[j]))
            j++, frac++;
        if (digits + frac == 0) return 0;
        i = j;
    } else if (digits == 0) {
        return 0;
    }
    if (s[i] == 'e' || s[i] == 'E') {
        size_t j = i + 1;
        if (s[j] == '+' || s[j] == '-') j++;
        if (isdigit((unsigned char)s[j])) {
            while (isdigit((unsigned char)s[j]))
                j++;
            i = j;
        }
    }
    return i;
}

/* The value of the numeral s[0..n) (number_length's syntax), as strtod
 * reads it: correctly rounded.  Most numerals in a model have a few digits
 * and a small exponent, and for those Clinger's fast path is exact: with the
 * digits as an integer m < 2^53 and the decimal exponent e in -22..22, m and
 * 10^|e| are both doubles, so the one multiplication or division rounds
 * correctly.  Everything else (long digit strings, big exponents) goes to
 * strtod, which costs about twenty times as much.  Returns -1 when a copy
 * for strtod cannot be made (out of memory). */
static int number_value(scad_arena *a, const char *s, size_t n, double *out)
{
    static const double p10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                 1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
    uint64_t m = 0;
    int sig = 0, e = 0, fast = 1;
    size_t i = 0;
    for (int frac = 0; i < n; i++) {
        if (s[i] == '.') {
            frac = 1;
            continue;
        }
        if (!isdigit((unsigned char)s[i])) break;
        if (m > 0 || s[i] != '0') sig++;
        if (sig > 15) fast = 0; /* m < 10^15 < 2^53 */
        m = m * 10 + (uint64_t)(s[i] - '0');
        e -= frac;
    }
    if (fast && i < n) { /* the exponent: e, E, an optional sign, digits */
        i++;
        int neg = s[i] == '-';
        if (s[i] == '+' || s[i] == '-') i++;
        int x = 0;
        for (; i < n && x < 1000; i++)
            x = x * 10 + (s[i] - '0');
        fast = i == n;
        e += neg ? -x : x;
    }
    if (fast && m == 0) {
        *out = 0;
        return 0;
    }
    if (fast && e >= -22 && e <= 22) {
        *out = e < 0 ? (double)m / p10[-e] : (double)m * p10[e];
        return 0;
    }
    char tmp[128], *buf = n < sizeof tmp ? tmp : scad_arena_alloc_raw(a, n + 1);
    if (!buf) return -1;
    memcpy(buf, s, n);
    buf[n] = 0;
    *out = strtod(buf, NULL);
    return 0;
}

static int hexval(int c)
{
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

static size_t put_utf8(char *o, unsigned long cp)
{
    if (cp < 0x80) {
        o[0] = (char)cp;
        return 1;
    }
    if (cp < 0x800) {
        o[0] = (char)(0xC0 | (cp >> 6));
        o[1] = (char)(0x80 | (cp & 0x3F));
        return 2;
    }
    if (cp < 0x10000) {
        o[0] = (char)(0xE0 | (cp >> 12));
        o[1] = (char)(0x80 | ((cp >> 6) & 0x3F));
        o[2] = (char)(0x80 | (cp & 0x3F));
        return 3;
    }
    o[0] = (char)(0xF0 | (cp >> 18));
    o[1] = (char)(0x80 | ((cp >> 12) & 0x3F));
    o[2] = (char)(0x80 | ((cp >> 6) & 0x3F));
    o[3] = (char)(0x80 | (cp & 0x3F));
    return 4;
}

/* A string literal starting at the opening quote. */
static void lex_string(lexer *L, scad_loc loc)
{
    const char *s = L->p + 1;
    size_t cap = 0;
    while (s[cap] && s[cap] != '"')
        cap += (s[cap] == '\\' && s[cap + 1]) ? 2 : 1;
    char *buf = scad_arena_alloc(L->a, cap + 8);
    if (!buf) {
        out_of_memory(L);
        return;
    }
    size_t n = 0;
    advance(L, 1);
    for (;;) {
        char c = *L->p;
        if (c == 0) {
            scad_diag_lex_error(L->d, loc, eof_line(L), "Unterminated string",
                                "unterminated string");
            L->failed = 1;
            break;
        }
        if (c == '"') {
            advance(L, 1);
            break;
        }
        if (c == '\n') { /* a line break in a literal is dropped, as 2021.01's lexer does */
            advance(L, 1);
            continue;
        }
        if (c != '\\') {
            buf[n++] = c;
            advance(L, 1);
            continue;
        }
        char e = L->p[1];
        size_t used = 2;
        switch (e) {
        case 'n':
            buf[n++] = '\n';
            break;
        case 't':
            buf[n++] = '\t';
            break;
        case 'r':
            buf[n++] = '\r';
            break;
        case '\\':
            buf[n++] = '\\';
            break;
        case '"':
            buf[n++] = '"';
            break;
        case 'x': {
            int h1 = hexval(L->p[2]), h2 = h1 >= 0 ? hexval(L->p[3]) : -1;
            if (h1 >= 0 && h1 <= 7 && h2 >= 0) {
                int ch = h1 * 16 + h2;
                buf[n++] = ch ? (char)ch : ' '; /* \x00 is a space, as in 2021.01 */
                used = 4;
            } else {
                buf[n++] = 'x';
            }
            break;
        }
        case 'u':
        case 'U': {
            int want = e == 'u' ? 4 : 6, k;
            unsigned long cp = 0;
            for (k = 0; k < want; k++) {
                int h = hexval(L->p[2 + k]);
                if (h < 0) break;
                cp = cp * 16 + (unsigned long)h;
            }
            if (k == want) {
                /* \u0000, a surrogate and a number past U+10FFFF are a
                 * space, as in 2021.01 (which takes what glib cannot
                 * encode for one) */
                if (cp == 0 || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF))
                    buf[n++] = ' ';
                else
                    n += put_utf8(buf + n, cp);
                used = 2 + (size_t)want;
            } else {
                buf[n++] = e;
            }
            break;
        }
        case 0:
            used = 1;
            break;
        default:
            buf[n++] = e;
            break;
        }
        advance(L, used);
    }
    buf[n] = 0;
    scad_token *t = push(L, TK_STRING, loc);
    if (!t) return;
    t->text = buf;
    t->len = n;
}

/* include <path> / use <path>: returns 1 when one was lexed.  As
 * openscad 2021.01's lexer: whitespace may stand between the word and '<',
 * tabs and line breaks inside the brackets separate pieces of which the
 * last folder part ("a/b/") and the last name part count, and the line
 * breaks from the word to '>' are not counted. */
static int lex_include(lexer *L, scad_loc loc, size_t wordlen, scad_tok_kind kind)
{
    const char *q = L->p + wordlen;
    while (*q == ' ' || *q == '\t' || *q == '\r' || *q == '\n')
        q++;
    if (*q != '<') return 0;
    const char *end = strchr(q, '>');
    if (!end) {
        int is_use = kind == TK_USE;
        scad_diag_lex_error(L->d, loc, L->line,
                            is_use ? "Unterminated use statement"
                                   : "Unterminated include statement",
                            is_use ? "unterminated file name after 'use'"
                                   : "unterminated file name after 'include'");
        L->failed = 1;
        return 1;
    }
    const char *dir = NULL, *name = NULL;
    size_t dirlen = 0, namelen = 0;
    for (const char *p = q + 1; p < end;) {
        size_t n = strcspn(p, "\t\r\n>");
        const char *piece = p, *slash = NULL;
        for (size_t i = 0; i < n; i++)
            if (piece[i] == '/') slash = piece + i;
        if (slash) {
            dir = piece;
            dirlen = (size_t)(slash - piece) + 1;
        }
        if (piece + n > (slash ? slash + 1 : piece)) {
            name = slash ? slash + 1 : piece;
            namelen = (size_t)(piece + n - name);
        }
        p += n;
        while (p < end && (*p == '\t' || *p == '\r' || *p == '\n'))
            p++;
    }
    char *text = scad_arena_alloc(L->a, dirlen + namelen + 1);
    if (!text) {
        out_of_memory(L);
        return 1;
    }
    if (dirlen) memcpy(text, dir, dirlen);
    if (namelen) memcpy(text + dirlen, name, namelen);
    text[dirlen + namelen] = 0;
    scad_token *t = push(L, kind, loc);
    if (!t) return 1;
    t->text = text;
    t->len = dirlen + namelen;
    advance_uncounted(L, (size_t)(end - L->p) + 1);
    return 1;
}

int scad_lex(scad_arena *a, scad_diag *d, scad_names *names, const char *file, const char *src,
             scad_token **out)
{
    lexer L = {a, d, names, file, src, 1, 1, NULL, 0, 0, 0, 0};
    while (!L.failed) {
        char c = *L.p;
        scad_loc loc = {file, L.line, L.col};
        if (c == 0) break;
        if (isspace((unsigned char)c) || (unsigned char)c == 0xa0) {
            advance(&L, 1); /* a Latin-1 no-break space too */
            continue;
        }
        if ((unsigned char)c == 0xc2 && (unsigned char)L.p[1] == 0xa0) {
            advance(&L, 2); /* and a UTF-8 one */
            continue;
        }
        if (c == '/' && L.p[1] == '/') {
            while (*L.p && *L.p != '\n')
                advance(&L, 1);
            continue;
        }
        if (c == '/' && L.p[1] == '*') {
            const char *end = strstr(L.p + 2, "*/");
            if (!end) {
                advance(&L, strlen(L.p));
                scad_diag_lex_error(d, loc, eof_line(&L), "Unterminated comment",
                                    "unterminated comment");
                break;
            }
            advance(&L, (size_t)(end - L.p) + 2);
            continue;
        }
        if (c == '"') {
            lex_string(&L, loc);
            continue;
        }
        size_t nl = number_length(L.p);
        size_t il = 0;
        if (c == '$') {
            il = 1;
            while (is_idch((unsigned char)L.p[il]))
                il++;
            if (il == 1) il = 0;
        } else {
            while (is_idch((unsigned char)L.p[il]))
                il++;
        }
        if (nl > 0 && nl >= il) {
            double x;
            if (number_value(a, L.p, nl, &x) != 0) {
                out_of_memory(&L);
                break;
            }
            /* a numeral too large for a double makes no token at all in
             * 2021.01 (its lexical_cast fails and the text is dropped):
             * echo(1e400) echoes nothing, -1e400 is a syntax error */
            if (!isinf(x)) {
                scad_token *t = push(&L, TK_NUMBER, loc);
                if (!t) break;
                t->num = x;
            }
            advance(&L, nl);
            continue;
        }
        if (il > 0) {
            if (il == 7 && memcmp(L.p, "include", 7) == 0 && lex_include(&L, loc, 7, TK_INCLUDE))
                continue;
            if (il == 3 && memcmp(L.p, "use", 3) == 0 && lex_include(&L, loc, 3, TK_USE)) continue;
            const char *name = scad_names_intern(L.names, L.p, il);
            if (!name) {
                out_of_memory(&L);
                break;
            }
            int keyword = scad_name_keyword(name);
            scad_token *t = push(&L, keyword ? (scad_tok_kind)keyword : TK_ID, loc);
            if (!t) break;
            t->text = name;
            t->len = il;
            advance(&L, il);
            continue;
        }
        static const struct {
            char s[3];
            scad_tok_kind kind;
        } two[] = {{"<=", TK_LE}, {">=", TK_GE},  {"==", TK_EQ},
                   {"!=", TK_NE}, {"&&", TK_AND}, {"||", TK_OR}};
        int done = 0;
        for (size_t k = 0; k < sizeof two / sizeof two[0]; k++) {
            if (c == two[k].s[0] && L.p[1] == two[k].s[1]) {
                push(&L, two[k].kind, loc);
                advance(&L, 2);
                done = 1;
                break;
            }
        }
        if (done) continue;
        if (strchr("+-*/%^<>!?:=.,;()[]{}#", c)) {
            scad_token *t = push(&L, TK_CHAR, loc);
            if (!t) break;
            t->ch = c;
            advance(&L, 1);
            continue;
        }
        scad_diag_syntax(d, loc);
        scad_diag_error(d, loc, "unexpected character '%c'", isprint((unsigned char)c) ? c : '?');
        advance(&L, 1);
    }
    scad_loc loc = {file, L.line, L.col};
    if (L.oom || !push(&L, TK_EOF, loc)) {
        free(L.v);
        *out = NULL;
        return 0;
    }
    *out = L.v;
    return L.n;
}
