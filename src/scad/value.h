/*
 * value.h — private to src/scad: OpenSCAD values and a growable text buffer.
 *
 * Values are small structs passed by value.  Strings, vectors, ranges and
 * function literals live on the heap with a reference count: a scad_value
 * held in a variable, a vector or a return slot owns one reference;
 * scad_value_ref adds one, scad_value_drop gives one back.  Heap values are
 * immutable once built, so sharing is safe.
 */
#ifndef RAYSCAD_SCAD_VALUE_H
#define RAYSCAD_SCAD_VALUE_H

#include <stddef.h>

#include "ast.h"

typedef enum scad_vkind { SV_UNDEF, SV_BOOL, SV_NUM, SV_STR, SV_VEC, SV_RANGE, SV_FUNC } scad_vkind;

typedef struct scad_str scad_str;
typedef struct scad_vec scad_vec;
typedef struct scad_range scad_range;
typedef struct scad_func scad_func;
typedef struct scad_env scad_env;

typedef struct scad_value {
    scad_vkind kind;
    union {
        int b;
        double num;
        scad_str *str;
        scad_vec *vec;
        scad_range *range;
        scad_func *func;
    } u;
} scad_value;

struct scad_str {
    int refs;
    size_t len;
    size_t nchars; /* UTF-8 code points */
    char s[];      /* NUL-terminated */
};

struct scad_vec {
    int refs;
    int n;
    scad_value v[];
};

struct scad_range {
    int refs;
    double begin, step, end;
};

/* A function literal: its parameters and body (borrowed from the AST) and
 * the environment it closes over (kept alive by the evaluator). */
struct scad_func {
    int refs;
    const scad_expr *lit;
    scad_env *env;
};

static inline scad_value scad_undef(void)
{
    scad_value v;
    v.kind = SV_UNDEF;
    v.u.num = 0;
    return v;
}
static inline scad_value scad_num(double d)
{
    scad_value v;
    v.kind = SV_NUM;
    v.u.num = d;
    return v;
}
static inline scad_value scad_bool(int b)
{
    scad_value v;
    v.kind = SV_BOOL;
    v.u.b = b != 0;
    return v;
}

/* Constructors return an owned value, or undef when out of memory. */
/* Bytes of the character at s[pos] as glib steps over UTF-8 (the lead
 * byte's length, valid or not, as OpenSCAD iterates and indexes strings),
 * within len. */
size_t scad_utf8_char_len(const char *s, size_t pos, size_t len);
scad_value scad_str_new(const char *s, size_t len);
/* A vector of n undef elements, to be filled in place before sharing. */
scad_value scad_vec_new(int n);
scad_value scad_range_new(double begin, double step, double end);
scad_value scad_func_new(const scad_expr *lit, scad_env *env);

scad_value scad_value_ref(scad_value v);
void scad_value_drop(scad_value v);

/* OpenSCAD's truth: false, 0, "", [] and undef are false; NaN is true. */
int scad_value_truthy(scad_value v);
/* Deep equality (==): same kind and equal; 1 == true is false. */
int scad_value_equal(scad_value a, scad_value b);
/* Ordering for < and min/max: -1, 0, 1, or 2 when the two cannot be
 * ordered (different kinds, NaN); vectors compare lexicographically. */
int scad_value_compare(scad_value a, scad_value b);
/* The type name in OpenSCAD's warnings: "undefined", "number" … */
const char *scad_value_type_name(scad_value v);
/* Values in a range, OpenSCAD's count (UINT32_MAX for endless ones). */
double scad_range_steps(const scad_range *r);
/* Its value number i: begin itself first (-0 stays -0, an infinite step
 * does not make it NaN), then begin + i * step, as OpenSCAD's iterator. */
double scad_range_at(const scad_range *r, double i);
/* Number of elements a range yields, or -1 when infinite / invalid. */
double scad_range_count(const scad_range *r);

/* ---- text --------------------------------------------------------------- */

/* Default size limits of values (scad_options.max_list, max_string): a
 * list of more elements, or a string of more bytes, is refused with a named
 * error ("list longer than … elements") — about 1 GB each, far beyond any
 * real model, well before the machine's memory runs out.  SCAD_MAX_LIST
 * also bounds every list, whatever the option says. */
enum { SCAD_MAX_LIST = 1 << 26, SCAD_MAX_STRING = 1 << 28 };

/* A growing text.  oom: an allocation failed or the text would pass limit
 * bytes (0: SCAD_MAX_STRING) — too_long says which; it then stops growing. */
typedef struct scad_buf {
    char *p;
    size_t n, cap;
    int oom, too_long;
    int too_deep; /* scad_value_format met a vector nested SCAD_MAX_NESTING deep */
    size_t limit;
} scad_buf;

void scad_buf_put(scad_buf *b, const char *s, size_t n);
void scad_buf_puts(scad_buf *b, const char *s);
void scad_buf_printf(scad_buf *b, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
void scad_buf_free(scad_buf *b);
/* The text so far, NUL-terminated ("" when empty or out of memory). */
const char *scad_buf_str(scad_buf *b);

/* Number text as OpenSCAD prints it: 6 significant digits, trailing zeros
 * dropped, exponent form below 1e-5 and from 1e6 up ("1e+6"), "-0" as "0",
 * "inf", "-inf", "nan".  buf must hold 32 bytes. */
void scad_format_number(double d, char *buf);
/* v as echo() and str() print it; quote_strings: strings in quotes (echo,
 * and any string inside a vector). */
/* Vectors nested this deep are not printed: the text would be quadratic
 * in the nesting of a recursion that wraps a value each call (openscad
 * 2021.01 crashes there, its stack exhausted at about 22,000 levels). */
enum { SCAD_MAX_NESTING = 10000 };
/* v as OpenSCAD prints it; strings quoted or not; b->too_deep when v is
 * nested SCAD_MAX_NESTING deep (the text then stops short). */
void scad_value_format(scad_buf *b, scad_value v, int quote_strings);
/* An operator's text: "<=" for TK_LE, "+" for '+' (written into buf, which
 * must hold 2 bytes, when one character). */
const char *scad_op_text(int op, char buf[2]);
/* s[0..n) in double quotes with OpenSCAD's QuotedString escapes (\t \n
 * \r \" \\; every other byte as it is), as it prints string literals in
 * expressions. */
void scad_quote_escaped(scad_buf *b, const char *s, size_t n);
/* An expression as OpenSCAD 2021.01 prints it (Expression::print: function
 * literals in echo, assert's condition, the .ast): "(x * 2)". */
void scad_expr_format(scad_buf *b, const scad_expr *e);

#endif
