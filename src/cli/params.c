/*
 * params.c — a customizer parameter file (-p FILE.json -P SET) read with
 * json-c and turned into -D assignments that do what openscad 2021.01 does
 * with it.  Nothing here evaluates OpenSCAD: the caller says what type
 * each default has (params.h), and every value leaves as the text of a
 * literal that evaluates to exactly the value openscad would have used.
 *
 * openscad 2021.01, measured (openscad -o x.echo -p F.json -P SET f.scad,
 * headless) and read in its source (parameter/parameterset.cc,
 * comment_lexer.l, comment_parser.y, openscad.cc):
 *
 * - Only -p and -P together, both non-empty, do anything: the file is read
 *   after the .scad file is parsed.  -p alone, -P alone: silently nothing,
 *   exit 0.
 * - The file: {"parameterSets": {"SET": {"var": "value", ...}, ...},
 *   "fileFormatVersion": "1"}, read by boost::property_tree::read_json;
 *   fileFormatVersion is never looked at.  The GUI writes every value as a
 *   JSON string ("7", "true", "hello", "[1, 2]").  A value's text ("data")
 *   is the string's contents; for a number, true, false or null its source
 *   text ("1.50", "1E+2", "-0", "true", "null"); for an array or object "".
 * - No file, an unreadable one: "ERROR: Cannot open Parameter Set 'F': F:
 *   cannot open file"; bad JSON: "ERROR: Cannot open Parameter Set 'F':
 *   F(LINE): expected value" in boost's words ("garbage after data",
 *   "expected key string", "expected ':'", "expected '}' or ','",
 *   "expected ']' or ','", "unterminated string", "invalid escape
 *   sequence", "invalid code sequence" for raw control characters, NUL or
 *   bad UTF-8, ...).  It goes on without parameters, exit 0.  These ERRORs
 *   are ordinary messages: in the .echo file when writing one, else on
 *   stderr.  A UTF-8 byte-order mark is skipped.
 * - A root without members ({}, [], a scalar): nothing.  A root with
 *   members but no "parameterSets", or a folder given as the file: openscad
 *   aborts (a failed assertion, an uncaught exception; exit 134), the
 *   first only when the .scad file has a top-level assignment.
 * - An unknown set: no message, exit 0; the members of "parameterSets"
 *   themselves are taken as the set (a variable named like a set gets that
 *   set's data, "" for an object), which usually changes nothing.
 * - For each top-level assignment of the file, in file order (-D ones
 *   included: -D has replaced the expression by then, so a set overrides
 *   -D), and each member of the set with its name, the current expression
 *   is evaluated in an empty context (no variables, no builtins, its
 *   warnings printed) and its type decides:
 *     string: the data, verbatim, becomes the value (9 gives "9");
 *     bool: the data read as C++'s `is >> b`, then `is >> boolalpha >> b`
 *       from where that stopped, then whitespace, then the end: "true",
 *       "false", "0", "1", "01", "+1", "-0", " true\n", "-true" pass;
 *       "True", "yes", "2", "1.0", "" fail with "ERROR: Cannot apply
 *       Parameter Set 'conversion of data to type "b" failed'", and the
 *       assignments after it (file order) are left alone, those before it
 *       keep their new values; exit 0;
 *     any other type (number, vector, range, undef, function): the data is
 *       parsed by the customizer's comment grammar (below) and used only if
 *       that value's type is the default's; otherwise silently nothing.
 *       So numbers replace numbers, flat vectors vectors, ranges ranges;
 *       undef and function defaults never change.  That evaluation prints
 *       a range's messages, with no location: [b:e] with e < b becomes
 *       [e:b] with "DEPRECATED: Using ranges of the form [begin:end] with
 *       begin value greater than the end value is deprecated" (once a
 *       run: openscad prints a deprecation once); [b:s:e] with s > 0 and
 *       e < b "WARNING: begin is greater than the end, but step is
 *       positive", s < 0 and e > b "... smaller than the end, but step is
 *       negative", at every check and again where the value is used.
 *   A member naming no top-level variable is ignored.
 * - The comment grammar.  Tokens, longest match first: a number
 *   [+-]?(D+|D*.D+|D+.D*)([eE][+-]?D+)? (dropped when it overflows a
 *   double; 1e-400 is 0); [ ] , : ; "..." a word, to the next quote or
 *   the end, with \n \t \r \\ \" decoded and any other backslash and
 *   any newline dropped (flex's default rule, which also writes them to
 *   openscad's stdout; we don't); a run of anything but space ( ) [ ] , : "
 *   a word; space, tab, ( and ) are skipped.  A value is NUM; or words: a
 *   run of numbers and words holding at least one word, joined by single
 *   spaces, numbers as %g ("abc 1.23456789" is "abc 1.23457"); or
 *   [NUM:NUM] or [NUM:NUM:NUM] (a range, begin:step:end); or [item, ...]
 *   with each item a NUM, words, or a pair a:b (a 2-vector).  Nested
 *   vectors, [], expressions such as 2*3 do not parse; true, undef, "5"
 *   are strings.
 *
 * Where json-c and boost differ (documented, not worked around): json-c
 * keeps the last of duplicate keys (boost applies each in turn, and finds
 * the first set or "parameterSets" of a name); it writes an integer back
 * as int64 (-0 is "0", integers past 64 bits are clamped); it accepts some
 * JSON boost rejects ('single quotes', raw tabs in strings, NaN, 1., lone
 * surrogates); its errors are worded in boost's words where they map one
 * to one, and its end-of-data errors after some JSON read "unexpected end
 * of data".  A
 * string value holding \u0000 ends there.
 */
#include "params.h"

#include <errno.h>
#include <json-c/json.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { MAX_FILE_BYTES = 64 << 20, MAX_DEPTH = 1000 };

/* ---- growing strings -------------------------------------------------------- */

typedef struct sbuf {
    char *p;
    size_t n, cap;
    int oom;
} sbuf;

static void put_mem(sbuf *b, const char *s, size_t n)
{
    if (b->oom) return;
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

static void put(sbuf *b, const char *s)
{
    put_mem(b, s, strlen(s));
}

/* A number as the shortest %g that reads back as the same double, which
 * rayscad's lexer reads exactly (strtod).  Never inf or nan here. */
static void put_number(sbuf *b, double x)
{
    char t[32];
    for (int prec = 15; prec <= 17; prec++) {
        snprintf(t, sizeof t, "%.*g", prec, x);
        if (strtod(t, NULL) == x) break;
    }
    put(b, t);
}

/* An OpenSCAD string literal holding s[0..n) byte for byte. */
static void put_string(sbuf *b, const char *s, size_t n)
{
    put(b, "\"");
    size_t from = 0;
    for (size_t i = 0; i < n; i++) {
        const char *esc = s[i] == '"'    ? "\\\""
                          : s[i] == '\\' ? "\\\\"
                          : s[i] == '\n' ? "\\n"
                          : s[i] == '\t' ? "\\t"
                          : s[i] == '\r' ? "\\r"
                                         : NULL;
        if (!esc) continue;
        put_mem(b, s + from, i - from);
        put(b, esc);
        from = i + 1;
    }
    put_mem(b, s + from, n - from);
    put(b, "\"");
}

/* ---- the comment grammar ---------------------------------------------------- */

typedef enum { T_NUM, T_WORD, T_CHAR } tkind;

typedef struct token {
    tkind kind;
    char ch;          /* T_CHAR: [ ] , : */
    double num;       /* T_NUM */
    const char *text; /* T_WORD: text[0..len) */
    size_t len;
} token;

static int is_digit(char c)
{
    return c >= '0' && c <= '9';
}

static size_t digits(const char *s)
{
    size_t n = 0;
    while (is_digit(s[n]))
        n++;
    return n;
}

/* The length of the number token at s: [+-]?(D+|D*.D+|D+.D*)([eE][+-]?D+)?,
 * 0 when there is none. */
static size_t number_length(const char *s)
{
    size_t i = s[0] == '+' || s[0] == '-';
    size_t whole = digits(s + i), end = 0;
    i += whole;
    if (whole) end = i;
    if (s[i] == '.') {
        size_t frac = digits(s + i + 1);
        if (whole || frac) end = i + 1 + frac;
    }
    if (end && (s[end] == 'e' || s[end] == 'E')) {
        size_t j = end + 1 + (s[end + 1] == '+' || s[end + 1] == '-');
        size_t ex = digits(s + j);
        if (ex) end = j + ex;
    }
    return end;
}

/* A word run's length: anything but space ( ) [ ] , : " and NUL. */
static size_t word_length(const char *s)
{
    size_t n = 0;
    while (s[n] && !strchr(" ()[],:\"", s[n]))
        n++;
    return n;
}

/* Split s as 2021.01's comment lexer does, a quoted word's text decoded
 * into words (room for strlen(s) + 1).  *n tokens in t (room for
 * strlen(s) + 1); 0, or -1 out of memory. */
static int tokenize(const char *s, token *t, int *n, char *words)
{
    int k = 0;
    while (*s) {
        if (strchr("[],:", *s)) {
            t[k++] = (token){.kind = T_CHAR, .ch = *s};
            s++;
            continue;
        }
        if (*s == '"') { /* to the next quote or the end, as flex's cond_string */
            char *w = words;
            for (s++; *s && *s != '"'; s++) {
                if (*s == '\\' && s[1] && strchr("ntr\\\"", s[1])) {
                    s++;
                    *w++ = *s == 'n' ? '\n' : *s == 't' ? '\t' : *s == 'r' ? '\r' : *s;
                } else if (*s != '\\' && *s != '\n') {
                    *w++ = *s;
                } /* other backslashes and newlines: dropped (flex echoes them) */
            }
            if (*s) s++;
            t[k++] = (token){.kind = T_WORD, .text = words, .len = (size_t)(w - words)};
            words = w;
            continue;
        }
        size_t word = word_length(s), num = number_length(s);
        /* flex: the longest match, the earlier rule on a tie (number before
         * word, blank before word: a lone tab is a blank, a tab that starts
         * a longer run is part of a word). */
        if (num && num == word) {
            char buf[512], *copy = num < sizeof buf ? buf : malloc(num + 1);
            if (!copy) return -1;
            memcpy(copy, s, num);
            copy[num] = 0;
            double x = strtod(copy, NULL);
            if (copy != buf) free(copy);
            if (isfinite(x)) t[k++] = (token){.kind = T_NUM, .num = x}; /* else dropped */
            s += num;
        } else if (word > 1 || (word == 1 && *s != '\t')) {
            t[k++] = (token){.kind = T_WORD, .text = s, .len = word};
            s += word;
        } else {
            s++; /* space, tab, ( ) */
        }
    }
    *n = k;
    return 0;
}

typedef struct gparser {
    const token *t;
    int n, pos;
    sbuf *out;
    const char *note; /* what evaluating the range prints, or NULL */
} gparser;

static const char deprecated_range[] = "DEPRECATED: Using ranges of the form [begin:end] with "
                                       "begin value greater than the end value is deprecated";

static int at_char(const gparser *g, int i, char c)
{
    return g->pos + i < g->n && g->t[g->pos + i].kind == T_CHAR && g->t[g->pos + i].ch == c;
}

static int at_num(const gparser *g, int i)
{
    return g->pos + i < g->n && g->t[g->pos + i].kind == T_NUM;
}

/* A run of numbers and words: one number (CLI_PARAM_NUMBER), words with
 * numbers (CLI_PARAM_STRING, joined by spaces), or -1. */
static int run(gparser *g, sbuf *out)
{
    int from = g->pos, words = 0;
    while (g->pos < g->n && g->t[g->pos].kind != T_CHAR)
        words += g->t[g->pos++].kind == T_WORD;
    int len = g->pos - from;
    if (len == 1 && !words) {
        put_number(out, g->t[from].num);
        return CLI_PARAM_NUMBER;
    }
    if (!words) return -1;
    sbuf s = {0};
    for (int i = from; i < g->pos; i++) {
        if (i > from) put(&s, " ");
        if (g->t[i].kind == T_WORD) {
            put_mem(&s, g->t[i].text, g->t[i].len);
        } else {
            char num[32];
            snprintf(num, sizeof num, "%g", g->t[i].num); /* ostream's default */
            put(&s, num);
        }
    }
    if (s.oom)
        out->oom = 1;
    else
        put_string(out, s.p ? s.p : "", s.n);
    free(s.p);
    return CLI_PARAM_STRING;
}

/* [NUM:NUM] or [NUM:NUM:NUM] at g->pos (the bison grammar shifts ']' there
 * rather than reduce a pair): its length in tokens, or 0. */
static int range_length(const gparser *g)
{
    if (!(at_char(g, 0, '[') && at_num(g, 1) && at_char(g, 2, ':') && at_num(g, 3))) return 0;
    if (at_char(g, 4, ']')) return 5;
    if (at_char(g, 4, ':') && at_num(g, 5) && at_char(g, 6, ']')) return 7;
    return at_char(g, 4, ':') ? -1 : 0; /* [1:2:x] is no pair either */
}

/* The whole token list as one value: its type, its literal in g->out; -1
 * when it does not parse. */
static int value(gparser *g)
{
    if (!at_char(g, 0, '[')) {
        int type = run(g, g->out);
        return type >= 0 && g->pos == g->n ? type : -1;
    }
    int range = range_length(g);
    if (range < 0) return -1;
    if (range) {
        /* 2021.01's Range::evaluate: [b:e] with e < b is [e:b], deprecated;
         * a literal [b:s:e] stepping away from e warns */
        double b = g->t[g->pos + 1].num, s = g->t[g->pos + 3].num, e = s;
        if (range == 5 && e < b) {
            e = b;
            b = s;
            g->note = deprecated_range;
        }
        if (range == 7) {
            e = g->t[g->pos + 5].num;
            if (s > 0 && e < b)
                g->note = "WARNING: begin is greater than the end, but step is positive";
            if (s < 0 && e > b)
                g->note = "WARNING: begin is smaller than the end, but step is negative";
        }
        put(g->out, "[");
        put_number(g->out, b);
        put(g->out, ":");
        if (range == 7) {
            put_number(g->out, s);
            put(g->out, ":");
        }
        put_number(g->out, e);
        put(g->out, "]");
        g->pos += range;
        return g->pos == g->n ? CLI_PARAM_RANGE : -1;
    }
    g->pos++;
    put(g->out, "[");
    for (int first = 1;; first = 0) {
        if (!first) put(g->out, ",");
        sbuf a = {0}, b = {0};
        int ok = run(g, &a) >= 0;
        if (ok && at_char(g, 0, ':')) { /* a pair a:b is [a, b] */
            g->pos++;
            ok = run(g, &b) >= 0;
            put(g->out, "[");
            put_mem(g->out, a.p ? a.p : "", a.n);
            put(g->out, ",");
            put_mem(g->out, b.p ? b.p : "", b.n);
            put(g->out, "]");
        } else {
            put_mem(g->out, a.p ? a.p : "", a.n);
        }
        if (a.oom || b.oom) g->out->oom = 1;
        free(a.p);
        free(b.p);
        if (!ok) return -1;
        if (at_char(g, 0, ']')) break;
        if (!at_char(g, 0, ',')) return -1;
        g->pos++;
    }
    g->pos++;
    put(g->out, "]");
    return g->pos == g->n ? CLI_PARAM_VECTOR : -1;
}

/* Data as the comment parser reads it (to its first NUL): the value's
 * type and literal appended to out, and in *note the message evaluating it
 * prints (NULL: none); -1 when it does not parse, -2 out of memory. */
static int comment_value(const char *data, sbuf *out, const char **note)
{
    *note = NULL;
    size_t len = strlen(data);
    token *t = malloc((len + 1) * sizeof *t);
    char *words = malloc(len + 1);
    int n, type = -2;
    if (t && words && tokenize(data, t, &n, words) == 0) {
        gparser g = {.t = t, .n = n, .out = out};
        type = value(&g);
        if (type >= 0) *note = g.note;
    }
    free(t);
    free(words);
    return type;
}

/* ---- booleans, as libstdc++ reads them -------------------------------------- */

static int is_space(char c)
{
    return c == ' ' || (c >= '\t' && c <= '\r');
}

/* boost's get_value<bool>: `is >> b`, on failure `is >> boolalpha >> b`
 * from where the first stopped, then optional whitespace and the end of
 * s[0..n) (a NUL in it is no end).  1 and *b, or 0. */
static int parse_bool(const char *s, size_t n, int *b)
{
    size_t i = 0;
    while (i < n && is_space(s[i]))
        i++;
    /* num_get into a long: a sign, digits; only 0 and 1 are a bool */
    int neg = 0, ok = 0;
    if (i < n && (s[i] == '+' || s[i] == '-')) neg = s[i++] == '-';
    size_t d = i;
    unsigned long long v = 0;
    int over = 0;
    for (; i < n && is_digit(s[i]); i++) {
        if (v > (~0ULL >> 1) / 10) over = 1;
        v = v * 10 + (unsigned)(s[i] - '0');
    }
    if (i > d && !over && (v == 0 || (v == 1 && !neg))) {
        *b = v == 1;
        ok = 1;
    }
    if (!ok) { /* boolalpha, after whitespace again */
        while (i < n && is_space(s[i]))
            i++;
        if (n - i >= 4 && !memcmp(s + i, "true", 4)) {
            *b = 1;
            i += 4;
        } else if (n - i >= 5 && !memcmp(s + i, "false", 5)) {
            *b = 0;
            i += 5;
        } else {
            return 0;
        }
    }
    while (i < n && is_space(s[i]))
        i++;
    return i == n;
}

/* ---- the file --------------------------------------------------------------- */

/* The line (from 1) of offset off. */
static int line_at(const char *s, size_t off)
{
    int line = 1;
    for (size_t i = 0; i < off; i++)
        line += s[i] == '\n';
    return line;
}

/* json-c's error in boost's words where they map one to one. */
static const char *error_words(enum json_tokener_error e, const char *text, size_t off, size_t len)
{
    char c = off < len ? text[off] : 0;
    switch (e) {
    case json_tokener_error_parse_object_key_name:
        return "expected key string";
    case json_tokener_error_parse_object_key_sep:
        return "expected ':'";
    case json_tokener_error_parse_object_value_sep:
        return "expected '}' or ','";
    case json_tokener_error_parse_array:
        return "expected ']' or ','";
    case json_tokener_error_parse_string:
        return "invalid escape sequence";
    case json_tokener_error_parse_utf8_string:
        return "invalid code sequence";
    case json_tokener_error_parse_boolean:
        return c == 't' ? "expected 'true'" : c == 'f' ? "expected 'false'" : "expected value";
    case json_tokener_error_parse_null:
        return c == 'n' ? "expected 'null'" : "expected value";
    case json_tokener_error_parse_unexpected: {
        size_t p = off;
        while (p > 0 && is_space(text[p - 1]))
            p--;
        return c == '}' && p > 0 && text[p - 1] == ',' ? "expected key string" : "expected value";
    }
    default:
        return json_tokener_error_desc(e);
    }
}

/* Read path whole.  0 and *text (NUL-terminated, *len bytes before it);
 * CLI_PARAMS_ERROR when it cannot be opened; CLI_PARAMS_FATAL when it
 * cannot be read, is too big, or memory runs out. */
static int read_file(const char *path, char **text, size_t *len, char *msg, size_t msglen)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        snprintf(msg, msglen, "Cannot open Parameter Set '%s': %s: cannot open file", path, path);
        return CLI_PARAMS_ERROR;
    }
    size_t n = 0, cap = 4096;
    char *p = malloc(cap);
    int rc = 0;
    while (p) {
        if (n + 1 == cap) {
            if (n > MAX_FILE_BYTES) {
                snprintf(msg, msglen, "Cannot open Parameter Set '%s': larger than %d MiB", path,
                         MAX_FILE_BYTES >> 20);
                rc = CLI_PARAMS_FATAL;
                break;
            }
            char *q = realloc(p, cap * 2);
            if (!q) break;
            p = q;
            cap *= 2;
        }
        size_t got = fread(p + n, 1, cap - 1 - n, f);
        n += got;
        if (got == 0) {
            if (ferror(f)) {
                snprintf(msg, msglen, "Cannot open Parameter Set '%s': %s: %s", path, path,
                         strerror(errno));
                rc = CLI_PARAMS_FATAL;
            }
            break;
        }
    }
    fclose(f);
    if (!p) {
        snprintf(msg, msglen, "out of memory reading '%s'", path);
        return CLI_PARAMS_FATAL;
    }
    if (rc != 0) {
        free(p);
        return rc;
    }
    p[n] = 0;
    *text = p;
    *len = n;
    return 0;
}

/* Parse text as JSON.  0 and *root (NULL for a JSON null), or
 * CLI_PARAMS_ERROR with openscad's message, or CLI_PARAMS_FATAL. */
static int parse_json(const char *path, const char *text, size_t len, json_object **root, char *msg,
                      size_t msglen)
{
    if (len >= 3 && !memcmp(text, "\xEF\xBB\xBF", 3)) { /* a byte-order mark */
        text += 3;
        len -= 3;
    }
    const char *words = NULL;
    size_t at = len;
    const char *nul = memchr(text, 0, len);
    struct json_tokener *tok = nul ? NULL : json_tokener_new_ex(MAX_DEPTH);
    *root = NULL;
    if (nul) {
        words = "invalid code sequence";
        at = (size_t)(nul - text);
    } else if (!tok) {
        snprintf(msg, msglen, "out of memory reading '%s'", path);
        return CLI_PARAMS_FATAL;
    } else {
        json_tokener_set_flags(tok, JSON_TOKENER_STRICT | JSON_TOKENER_ALLOW_TRAILING_CHARS |
                                        JSON_TOKENER_VALIDATE_UTF8);
        /* the NUL after the text too: the end of the input (a number's) */
        *root = json_tokener_parse_ex(tok, text, (int)len + 1);
        enum json_tokener_error e = json_tokener_get_error(tok);
        size_t end = json_tokener_get_parse_end(tok);
        if (e == json_tokener_error_depth) {
            json_tokener_free(tok);
            snprintf(msg, msglen, "Cannot open Parameter Set '%s': JSON nested deeper than %d",
                     path, MAX_DEPTH);
            return CLI_PARAMS_FATAL;
        }
        if (e == json_tokener_success) {
            while (end < len && is_space(text[end]) && text[end] != '\v' && text[end] != '\f')
                end++;
            if (end < len) {
                words = "garbage after data";
                at = end;
            }
        } else if (e == json_tokener_error_parse_eof) {
            size_t i = 0;
            while (i < len && is_space(text[i]))
                i++;
            words = i == len ? "expected value" : "unexpected end of data";
        } else {
            at = end;
            words = error_words(e, text, end, len);
        }
        json_tokener_free(tok);
    }
    if (!words) return 0;
    json_object_put(*root);
    *root = NULL;
    /* boost counts lines from 1, and an error at the end is on the last */
    snprintf(msg, msglen, "Cannot open Parameter Set '%s': %s(%d): %s", path, path,
             line_at(text, at), words);
    return CLI_PARAMS_ERROR;
}

/* A value's data as boost's ptree holds it (see the top). */
static const char *data_of(json_object *v, size_t *len)
{
    const char *s;
    switch (json_object_get_type(v)) {
    case json_type_null:
        s = "null";
        break;
    case json_type_object:
    case json_type_array:
        s = "";
        break;
    case json_type_string:
        *len = (size_t)json_object_get_string_len(v);
        return json_object_get_string(v);
    default: /* numbers as written (json-c keeps a double's text), booleans */
        s = json_object_get_string(v);
        break;
    }
    *len = strlen(s);
    return s;
}

/* A root with members, as boost's ptree::empty() would say. */
static int has_members(json_object *root)
{
    switch (json_object_get_type(root)) {
    case json_type_object:
        return json_object_object_length(root) > 0;
    case json_type_array:
        return json_object_array_length(root) > 0;
    default:
        return 0;
    }
}

/* Set `set`'s members for file into *out.  Returns as cli_params_load. */
static int apply(const char *path, json_object *root, const char *set, const cli_param_file *file,
                 char **out, int *count, char *msg, size_t msglen)
{
    if (!has_members(root) || file->count == 0) return CLI_PARAMS_OK;
    json_object *sets = NULL, *members = NULL;
    if (json_object_get_type(root) != json_type_object ||
        !json_object_object_get_ex(root, "parameterSets", &sets)) {
        snprintf(msg, msglen,
                 "Cannot apply Parameter Set: '%s' has no \"parameterSets\" (openscad 2021.01 "
                 "aborts here)",
                 path);
        return CLI_PARAMS_FATAL;
    }
    if (json_object_get_type(sets) != json_type_object) return CLI_PARAMS_OK;
    if (!json_object_object_get_ex(sets, set, &members)) members = sets; /* see the top */
    if (json_object_get_type(members) != json_type_object) return CLI_PARAMS_OK;
    int deprecated = 0;
    for (int i = 0; i < file->count; i++) {
        json_object *v;
        if (!json_object_object_get_ex(members, file->names[i], &v)) continue;
        size_t len;
        const char *data = data_of(v, &len);
        sbuf b = {0};
        put(&b, file->names[i]);
        put(&b, "=");
        cli_param_type want = file->default_type(file->ud, i);
        int use = 1;
        if (want == CLI_PARAM_STRING) {
            put_string(&b, data, strlen(data));
        } else if (want == CLI_PARAM_BOOL) {
            int on;
            if (!parse_bool(data, len, &on)) {
                free(b.p);
                snprintf(msg, msglen,
                         "Cannot apply Parameter Set 'conversion of data to type \"b\" failed'");
                return CLI_PARAMS_ERROR;
            }
            put(&b, on ? "true" : "false");
        } else {
            const char *note;
            int got = comment_value(data, &b, &note);
            if (got == -2) b.oom = 1;
            use = got == (int)want;
            /* openscad evaluates the value to learn its type; it prints a
             * deprecation once (so not again when the -D is evaluated:
             * the range comes out swapped) */
            if (note && file->message && (note != deprecated_range || !deprecated++))
                file->message(file->ud, note);
        }
        if (b.oom) {
            free(b.p);
            snprintf(msg, msglen, "out of memory applying parameter set '%s'", set);
            return CLI_PARAMS_FATAL;
        }
        if (use)
            out[(*count)++] = b.p;
        else
            free(b.p);
    }
    return CLI_PARAMS_OK;
}

int cli_params_load(const char *path, const char *set, const cli_param_file *file,
                    char ***assignments, int *count, char *msg, size_t msglen)
{
    *assignments = NULL;
    *count = 0;
    if (msglen) msg[0] = 0;
    if (!path || !*path || !set || !*set) return CLI_PARAMS_OK;
    char *text;
    size_t len;
    int rc = read_file(path, &text, &len, msg, msglen);
    if (rc != 0) return rc;
    json_object *root;
    rc = parse_json(path, text, len, &root, msg, msglen);
    free(text);
    if (rc != 0) return rc;
    char **out = file->count ? calloc((size_t)file->count, sizeof *out) : NULL;
    if (file->count && !out) {
        json_object_put(root);
        snprintf(msg, msglen, "out of memory applying parameter set '%s'", set);
        return CLI_PARAMS_FATAL;
    }
    int n = 0;
    rc = apply(path, root, set, file, out, &n, msg, msglen);
    json_object_put(root);
    if (rc == CLI_PARAMS_FATAL) {
        cli_params_free(out, n);
        return rc;
    }
    if (n == 0) {
        free(out);
        out = NULL;
    }
    *assignments = out;
    *count = n;
    return rc;
}

void cli_params_free(char **assignments, int count)
{
    if (!assignments) return;
    for (int i = 0; i < count; i++)
        free(assignments[i]);
    free(assignments);
}
