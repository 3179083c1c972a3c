/*
 * svg_parse.c — geom_svg_read: the SVG's XML parsed by libxml2 and walked
 * in document order as libsvg's xmlTextReader loop walks it.
 *
 * libsvg keeps a stack of the open containers (svg, g, text, tspan); an
 * element's parent is the container on top, so the children of elements it
 * does not know (a, switch, foo) belong to the nearest container above
 * them.  The transforms that apply to an element are its own and its
 * ancestors', except the first container's (the root, which has no
 * parent).  Elements between <defs> and the next </defs> draw nothing.
 *
 * The parse reads no network and no external entity (XML_PARSE_NONET, no
 * DTD loading or entity substitution) and prints nothing: its error comes
 * back as text.  libxml2 bounds the nesting depth (256 without
 * XML_PARSE_HUGE), which bounds the walk's recursion.
 */
#include "svg.h"

#include <libxml/parser.h>
#include <libxml/tree.h>

#include <stdio.h>
#include <string.h>

typedef struct walk {
    geom_svg *d;
    int in_defs;
} walk;

typedef struct elem {
    xmlNode *node;
    xmlChar *held[24]; /* attribute values handed out, freed after */
    int nheld;
} elem;

static const char *get_attr(void *ud, const char *name)
{
    elem *e = ud;
    if (e->nheld == (int)(sizeof e->held / sizeof *e->held)) return NULL;
    xmlChar *v = xmlGetNoNsProp(e->node, (const xmlChar *)name);
    if (v) e->held[e->nheld++] = v;
    return (const char *)v;
}

static int is_container(const char *name)
{
    return !strcmp(name, "svg") || !strcmp(name, "g") || !strcmp(name, "text") ||
           !strcmp(name, "tspan");
}

/* The node and what follows it; m: the top container's matrix, NULL when
 * the stack is empty.  0 or -1 (out of memory). */
static int visit(walk *w, xmlNode *n, const double *m)
{
    for (; n; n = n->next) {
        if (n->type != XML_ELEMENT_NODE) continue;
        const char *name = (const char *)n->name;
        if (!strcmp(name, "defs")) w->in_defs = 1;
        elem e = {n, {0}, 0};
        double mine[6];
        const double *inner = m;
        int rc = 0;
        if (!w->in_defs) rc = geom_svg_add_element(w->d, name, get_attr, &e, m);
        if (!rc && is_container(name)) {
            static const double id[6] = {1, 0, 0, 1, 0, 0};
            if (m)
                geom_svg_transform(get_attr(&e, "transform"), m, mine);
            else
                memcpy(mine, id, sizeof id);
            inner = mine;
        }
        for (int i = 0; i < e.nheld; i++)
            xmlFree(e.held[i]);
        if (rc) return -1;
        if (n->children && visit(w, n->children, inner)) return -1;
        if (!strcmp(name, "defs")) w->in_defs = 0;
    }
    return 0;
}

/* libxml2's structured error channel: the first error is kept (the last,
 * which xmlCtxtGetLastError keeps, is often "Premature end of data"). */
typedef struct first_error {
    int set, line, col;
    char msg[200];
} first_error;

static void on_error(void *ud, xmlErrorPtr e)
{
    xmlParserCtxtPtr ctxt = ud;
    first_error *f = ctxt ? ctxt->_private : NULL;
    if (!f || f->set || !e || e->level < XML_ERR_ERROR) return;
    f->set = 1;
    f->line = e->line;
    f->col = e->int2;
    size_t l = e->message ? strlen(e->message) : 0;
    while (l > 0 && (e->message[l - 1] == '\n' || e->message[l - 1] == ' '))
        l--;
    snprintf(f->msg, sizeof f->msg, "%.*s", (int)l, e->message ? e->message : "");
}

int geom_svg_read(const char *bytes, size_t len, geom_svg *out, char *err, size_t errlen)
{
    memset(out, 0, sizeof *out);
    if (errlen) err[0] = 0;
    if (len > (size_t)0x7fffffff) {
        snprintf(err, errlen, "the file is too large");
        return 1;
    }
    xmlParserCtxtPtr ctxt = xmlNewParserCtxt();
    if (!ctxt) return -1;
    first_error first = {0, 0, 0, ""};
    ctxt->_private = &first;
    if (ctxt->sax) ctxt->sax->serror = on_error;
    xmlDocPtr doc = xmlCtxtReadMemory(ctxt, bytes, (int)len, NULL, NULL,
                                      XML_PARSE_NONET | XML_PARSE_NOERROR | XML_PARSE_NOWARNING);
    if (!doc) {
        if (first.set)
            snprintf(err, errlen, "%d:%d: %s", first.line, first.col, first.msg);
        else
            snprintf(err, errlen, "not well-formed XML");
        xmlFreeParserCtxt(ctxt);
        return 1;
    }
    walk w = {out, 0};
    int rc = visit(&w, xmlDocGetRootElement(doc), NULL);
    xmlFreeDoc(doc);
    xmlFreeParserCtxt(ctxt);
    return rc;
}
