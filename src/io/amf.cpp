/*
 * amf.cpp — import() of AMF files as OpenSCAD 2021.01 reads them
 * (src/import_amf.cc there), behind io_amf_read of io.h.
 *
 * The file is streamed through libxml2's xmlTextReader, keeping the path of
 * open elements ("/amf/object/mesh/...") as the only state besides the
 * numbers read: the text of .../coordinates/x|y|z sets x, y, z, the end of
 * <coordinates> appends the vertex (x, y, z) to the object's vertex list,
 * the text of .../volume/triangle/v1|v2|v3 sets an index, the end of
 * <triangle> appends the triangle.  As there, the numbers persist from one
 * vertex or triangle to the next (a vertex without <z> takes the previous
 * z), every <volume> of an <object> adds to one list of triangles (never
 * unioned), the vertex list is the object's (cleared at </object>), and
 * everything else — units, colors, materials, metadata, constellations —
 * is ignored.  Element names are matched as written, prefix included.
 *
 * OpenSCAD unions the objects (CGAL); here they are concatenated into one
 * mesh, which is their union under the nonzero winding rule of
 * iv_shape_mesh and of the mesher, each object's vertices welded
 * (weld.h).  A parse error after some objects were complete keeps those
 * objects, as 2021.01 does; a triangle index out of the object's vertex
 * list (undefined behaviour there) is a parse error here.
 *
 * A file that is a ZIP archive (2021.01 is built with libzip) is read from
 * its entry named as the archive's own file name (any folder in the entry
 * ignored), or else from its only entry, with OpenSCAD's two warnings; the
 * uncompressed entry may be at most MAX_ENTRY_BYTES.
 *
 * Safety: the parser runs with XML_PARSE_NONET and without entity
 * substitution or DTD loading, so no external resource is ever read; its
 * error callback keeps the first error instead of printing it.  No C++
 * exception crosses the C boundary.
 *
 * io_amf_write writes AMF as 2021.01 exports it (src/export_amf.cc there):
 * the same elements, one-space indentation and CRLF line ends, one
 * <object id="0"> in millimetres, <metadata type="producer"> naming
 * rayscad.  It prints with stdio rather than libxml2's xmlTextWriter: the
 * file holds numbers and fixed tags only, nothing to escape, and 2021.01's
 * layout (<vertex><coordinates> on one line) is not one of xmlTextWriter's
 * indentations.  The one departure: numbers carry 9 significant digits
 * (%.9g, so each float reads back exactly) where 2021.01's ostream keeps
 * 6.  The file is written to io_temp_beside's temporary file and renamed
 * over path only once it was flushed and closed without error.
 */
#include <libxml/xmlreader.h>
#include <zip.h>

#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include <unistd.h>

#include "../../include/rayscad.h"
#include "export.h"
#include "io.h"
#include "temp_file.h"
#include "weld.h"

namespace
{

/* A decompressed AMF larger than this is refused (1 GiB: the limit on
 * mesh files elsewhere). */
const zip_uint64_t MAX_ENTRY_BYTES = (zip_uint64_t)1 << 30;

const char *const OBJECT = "/amf/object";
const char *const COORDINATES = "/amf/object/mesh/vertices/vertex/coordinates";
const char *const TRIANGLE = "/amf/object/mesh/volume/triangle";

struct Reader {
    std::string xpath; /* the open elements, "/a/b/c" */
    double x = 0, y = 0, z = 0;
    long long idx[3] = {0, 0, 0};
    std::vector<double> verts; /* the object's vertex list, 3 per vertex */
    std::vector<int64_t> tris; /* the object's triangles, into verts */
    std::vector<float> out_v;  /* the completed objects */
    std::vector<int32_t> out_t;
    std::string error; /* the first reason to stop, "" while none */
    int error_line = 0;
    std::string empty_element; /* the first <e/>, and its line */
    int empty_element_line = 0;
    bool after_empty_element = false; /* an element came after it */
    std::string xml_error;            /* libxml2's first error, and its line */
    int xml_error_line = 0;
};

void set_msg(char *msg, size_t msglen, const std::string &s)
{
    if (msg && msglen) std::snprintf(msg, msglen, "%s", s.c_str());
}

/* boost::lexical_cast<double> as 2021.01 uses it: the whole text is one
 * number, no spaces around it; inf and nan are numbers (as there). */
bool parse_double(const char *s, double *out)
{
    if (!*s || std::isspace((unsigned char)*s)) return false;
    const char *p = s + (*s == '+' || *s == '-');
    if (p[0] == '0' && (p[1] == 'x' || p[1] == 'X')) return false;
    char *end;
    errno = 0;
    double d = std::strtod(s, &end);
    if (end == s || *end) return false;
    *out = d;
    return true;
}

/* boost::lexical_cast<int>: an optional sign and decimal digits that fit
 * an int. */
bool parse_int(const char *s, long long *out)
{
    const char *p = s + (*s == '+' || *s == '-');
    if (!*p) return false;
    for (const char *q = p; *q; q++)
        if (!std::isdigit((unsigned char)*q)) return false;
    char *end;
    errno = 0;
    long long v = std::strtoll(s, &end, 10);
    if (errno || *end || v < INT32_MIN || v > INT32_MAX) return false;
    *out = v;
    return true;
}

void fail(Reader &r, xmlTextReaderPtr xr, const std::string &why)
{
    if (!r.error.empty()) return;
    r.error = why;
    /* the node's own line: the parser's position runs ahead of it */
    xmlNodePtr at = xmlTextReaderCurrentNode(xr);
    long line = at ? xmlGetLineNo(at) : -1;
    r.error_line = line > 0 ? (int)line : xmlTextReaderGetParserLineNumber(xr);
}

/* Append the object's triangles, and the vertices they use, to the output. */
bool end_object(Reader &r, xmlTextReaderPtr xr)
{
    if (!io_weld::append(r.verts, r.tris, r.out_v, r.out_t)) {
        fail(r, xr, "more than 2^31 vertices or triangles");
        return false;
    }
    r.verts.clear();
    r.tris.clear();
    return true;
}

/* One node of the stream; false to stop reading. */
bool node(Reader &r, xmlTextReaderPtr xr)
{
    int type = xmlTextReaderNodeType(xr);
    if (type == XML_READER_TYPE_ELEMENT) {
        const xmlChar *name = xmlTextReaderConstName(xr);
        if (!r.empty_element.empty()) r.after_empty_element = true;
        r.xpath += '/';
        r.xpath += name ? (const char *)name : "--";
        if (r.xpath == OBJECT) {
            r.verts.clear();
            r.tris.clear();
        }
        /* sic: an empty element <e/> has no end element of its own, and
         * 2021.01 never takes it off the path: every element after it is
         * one level deeper than its pattern and matches nothing */
        if (xmlTextReaderIsEmptyElement(xr) && r.empty_element.empty()) {
            r.empty_element = name ? (const char *)name : "--";
            xmlNodePtr at = xmlTextReaderCurrentNode(xr);
            long line = at ? xmlGetLineNo(at) : -1;
            r.empty_element_line = line > 0 ? (int)line : xmlTextReaderGetParserLineNumber(xr);
        }
        return true;
    }
    if (type == XML_READER_TYPE_END_ELEMENT) {
        bool ok = true;
        if (r.xpath == COORDINATES) {
            r.verts.push_back(r.x);
            r.verts.push_back(r.y);
            r.verts.push_back(r.z);
        } else if (r.xpath == TRIANGLE) {
            size_t n = r.verts.size() / 3;
            for (int k = 0; k < 3; k++)
                if (r.idx[k] < 0 || (size_t)r.idx[k] >= n) {
                    fail(r, xr,
                         "triangle vertex index " + std::to_string(r.idx[k]) +
                             " is out of range (the object has " + std::to_string(n) +
                             " vertices so far)");
                    return false;
                }
            for (int k = 0; k < 3; k++)
                r.tris.push_back(r.idx[k]);
        } else if (r.xpath == OBJECT) {
            ok = end_object(r, xr);
        }
        size_t slash = r.xpath.find_last_of('/');
        if (slash != std::string::npos) r.xpath.erase(slash);
        return ok;
    }
    if (type != XML_READER_TYPE_TEXT) return true;
    size_t slash = r.xpath.find_last_of('/');
    if (slash == std::string::npos) return true;
    const char *leaf = r.xpath.c_str() + slash + 1;
    const char *text = (const char *)xmlTextReaderConstValue(xr);
    if (!text) text = "";
    bool coordinate =
        (!std::strcmp(leaf, "x") || !std::strcmp(leaf, "y") || !std::strcmp(leaf, "z")) &&
        r.xpath.compare(0, slash, COORDINATES) == 0 && slash == std::strlen(COORDINATES);
    bool index =
        (!std::strcmp(leaf, "v1") || !std::strcmp(leaf, "v2") || !std::strcmp(leaf, "v3")) &&
        r.xpath.compare(0, slash, TRIANGLE) == 0 && slash == std::strlen(TRIANGLE);
    if (coordinate) {
        double *d = leaf[0] == 'x' ? &r.x : leaf[0] == 'y' ? &r.y : &r.z;
        if (!parse_double(text, d)) {
            fail(r, xr, std::string("<") + leaf + "> '" + text + "' is not a number");
            return false;
        }
    } else if (index) {
        if (!parse_int(text, &r.idx[leaf[1] - '1'])) {
            fail(r, xr, std::string("<") + leaf + "> '" + text + "' is not an index");
            return false;
        }
    }
    return true;
}

void on_xml_error(void *ud, xmlErrorPtr e)
{
    Reader *r = (Reader *)ud;
    if (!r || !e || !r->xml_error.empty()) return;
    std::string m = e->message ? e->message : "XML error";
    while (!m.empty() && (m.back() == '\n' || m.back() == ' '))
        m.pop_back();
    r->xml_error = m.empty() ? "XML error" : m;
    r->xml_error_line = e->line;
}

/* A ZIP entry as libxml2's input: bytes counted against MAX_ENTRY_BYTES. */
struct ZipInput {
    zip_file_t *file = nullptr;
    zip_uint64_t read = 0;
    bool too_big = false;
};

int zip_read_cb(void *ctx, char *buf, int len)
{
    ZipInput *z = (ZipInput *)ctx;
    zip_int64_t n = zip_fread(z->file, buf, (zip_uint64_t)len);
    if (n < 0) return -1;
    z->read += (zip_uint64_t)n;
    if (z->read > MAX_ENTRY_BYTES) {
        z->too_big = true;
        return -1;
    }
    return (int)n;
}

int zip_close_cb(void *)
{
    return 0; /* the entry is closed by read_amf */
}

const int XML_OPTIONS = XML_PARSE_NONET | XML_PARSE_NOERROR | XML_PARSE_NOWARNING;

/* Stream the document of xr into r.  1 when it was read to its end
 * without error. */
bool stream(Reader &r, xmlTextReaderPtr xr)
{
    xmlTextReaderSetStructuredErrorHandler(xr, on_xml_error, &r);
    int ret;
    while ((ret = xmlTextReaderRead(xr)) == 1)
        if (!node(r, xr)) return false;
    return ret == 0 && r.xml_error.empty();
}

std::string quoted(const char *path)
{
    return std::string("'") + path + "'";
}

struct FreeReader {
    void operator()(xmlTextReader *xr) const { xmlFreeTextReader(xr); }
};
struct CloseArchive {
    void operator()(zip_t *z) const { zip_close(z); }
};
struct CloseEntry {
    void operator()(zip_file_t *f) const { zip_fclose(f); }
};
typedef std::unique_ptr<xmlTextReader, FreeReader> ReaderPtr;

int read_amf(const char *path, float **v, int *nv, int32_t **t, int *nt, char *msg, size_t msglen)
{
    xmlInitParser();
    std::string warnings; /* lines, each ending in '\n' */
    Reader r;
    bool ok = false, opened = false;
    ZipInput zin;
    int zerr = 0;
    std::unique_ptr<zip_t, CloseArchive> archive(zip_open(path, ZIP_RDONLY, &zerr));
    if (archive) {
        const char *slash = std::strrchr(path, '/');
        const char *name = slash ? slash + 1 : path;
        std::unique_ptr<zip_file_t, CloseEntry> entry(zip_fopen(archive.get(), name, ZIP_FL_NODIR));
        if (!entry) {
            warnings += "Can't read file '" + std::string(name) + "' from zipped AMF " +
                        quoted(path) + "\n";
            if (zip_get_num_entries(archive.get(), 0) == 1) {
                const char *only = zip_get_name(archive.get(), 0, 0);
                warnings += "Trying to read single entry '" + std::string(only ? only : "") + "'\n";
                entry.reset(zip_fopen_index(archive.get(), 0, 0));
            }
        }
        if (entry) {
            zin.file = entry.get();
            ReaderPtr xr(
                xmlReaderForIO(zip_read_cb, zip_close_cb, &zin, name, nullptr, XML_OPTIONS));
            if (xr) {
                opened = true;
                ok = stream(r, xr.get());
            }
        }
    } else {
        ReaderPtr xr(xmlReaderForFile(path, nullptr, XML_OPTIONS));
        if (xr) {
            opened = true;
            ok = stream(r, xr.get());
        }
    }
    if (!opened) {
        set_msg(msg, msglen, warnings + "Can't open import file " + quoted(path));
        return -1;
    }
    if (!ok) {
        std::string why;
        if (zin.too_big)
            why = ": its uncompressed AMF is larger than " +
                  std::to_string((unsigned long long)MAX_ENTRY_BYTES) + " bytes";
        else if (!r.error.empty())
            why = ": line " + std::to_string(r.error_line) + ": " + r.error;
        else if (!r.xml_error.empty())
            why = ": line " + std::to_string(r.xml_error_line) + ": " + r.xml_error;
        warnings += "Failed to parse file " + quoted(path) + why + "\n";
    }
    if (r.after_empty_element)
        warnings += "note: " + quoted(path) + " line " + std::to_string(r.empty_element_line) +
                    ": nothing after the empty element <" + r.empty_element +
                    "/> is read, as in OpenSCAD 2021.01 (its AMF reader does not leave an "
                    "empty element)\n";
    if (!warnings.empty()) warnings.pop_back();
    if (r.out_t.empty()) {
        set_msg(msg, msglen, warnings);
        return ok ? 0 : -1;
    }
    float *vv = (float *)std::malloc(r.out_v.size() * sizeof(float));
    int32_t *tt = (int32_t *)std::malloc(r.out_t.size() * sizeof(int32_t));
    if (!vv || !tt) {
        std::free(vv);
        std::free(tt);
        set_msg(msg, msglen, std::string(path) + ": out of memory");
        return -1;
    }
    std::memcpy(vv, r.out_v.data(), r.out_v.size() * sizeof(float));
    std::memcpy(tt, r.out_t.data(), r.out_t.size() * sizeof(int32_t));
    *v = vv;
    *t = tt;
    *nv = (int)(r.out_v.size() / 3);
    *nt = (int)(r.out_t.size() / 3);
    set_msg(msg, msglen, warnings);
    return 0;
}

} // namespace

extern "C" int io_amf_read(const char *path, float **v, int *nv, int32_t **t, int *nt, char *msg,
                           size_t msglen)
{
    if (msg && msglen) msg[0] = 0;
    *v = nullptr;
    *t = nullptr;
    *nv = *nt = 0;
    try {
        return read_amf(path, v, nv, t, nt, msg, msglen);
    } catch (const std::bad_alloc &) {
        if (msg && msglen) std::snprintf(msg, msglen, "%s: out of memory", path ? path : "AMF");
        return -1;
    } catch (const std::exception &e) {
        if (msg && msglen) std::snprintf(msg, msglen, "%s: %s", path ? path : "AMF", e.what());
        return -1;
    } catch (...) {
        if (msg && msglen) std::snprintf(msg, msglen, "%s: AMF read failed", path ? path : "");
        return -1;
    }
}

namespace
{

/* The body of the AMF, into f (a stdio stream: its errors are sticky and
 * checked once, at the end). */
void print_amf(std::FILE *f, const float *v, int nv, const int32_t *t, int nt)
{
    std::fputs("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\r\n"
               "<amf unit=\"millimeter\">\r\n"
               " <metadata type=\"producer\">rayscad " RAYSCAD_VERSION_STRING "</metadata>\r\n"
               " <object id=\"0\">\r\n"
               "  <mesh>\r\n"
               "   <vertices>\r\n",
               f);
    for (size_t i = 0; i < (size_t)nv; i++) {
        const float *p = v + 3 * i;
        /* +0 for -0: the sign of a zero means nothing in a mesh */
        std::fprintf(f,
                     "    <vertex><coordinates>\r\n"
                     "     <x>%.9g</x>\r\n"
                     "     <y>%.9g</y>\r\n"
                     "     <z>%.9g</z>\r\n"
                     "    </coordinates></vertex>\r\n",
                     p[0] + 0.0, p[1] + 0.0, p[2] + 0.0);
    }
    std::fputs("   </vertices>\r\n"
               "   <volume>\r\n",
               f);
    for (size_t i = 0; i < (size_t)nt; i++) {
        const int32_t *q = t + 3 * i;
        std::fprintf(f,
                     "    <triangle>\r\n"
                     "     <v1>%d</v1>\r\n"
                     "     <v2>%d</v2>\r\n"
                     "     <v3>%d</v3>\r\n"
                     "    </triangle>\r\n",
                     (int)q[0], (int)q[1], (int)q[2]);
    }
    std::fputs("   </volume>\r\n"
               "  </mesh>\r\n"
               " </object>\r\n"
               "</amf>\r\n",
               f);
}

int write_amf(const char *path, const float *v, int nv, const int32_t *t, int nt, char *err,
              size_t errlen)
{
    std::string why = io_export::check(v, nv, t, nt);
    if (!why.empty()) {
        set_msg(err, errlen, std::string(path) + ": " + why);
        return -1;
    }
    std::vector<char> tmp(std::strlen(path) + 64);
    std::vector<char> buf((size_t)1 << 16); /* f's buffer: outlives it */
    if (io_temp_beside(path, tmp.data(), tmp.size(), err, errlen) != 0) return -1;
    errno = 0;
    std::FILE *f = std::fopen(tmp.data(), "wb");
    int saved = errno;
    int failed = !f;
    if (f) {
        std::setvbuf(f, buf.data(), _IOFBF, buf.size());
        errno = 0;
        print_amf(f, v, nv, t, nt);
        failed = std::ferror(f);
        saved = errno;
        if (std::fclose(f) != 0 && !failed) {
            failed = 1;
            saved = errno;
        }
    }
    if (failed) {
        unlink(tmp.data());
        set_msg(err, errlen,
                std::string(path) + ": writing failed" +
                    (saved ? std::string(": ") + std::strerror(saved) : std::string()));
        return -1;
    }
    return io_temp_commit(tmp.data(), path, err, errlen);
}

} // namespace

extern "C" int io_amf_write(const char *path, const float *v, int nv, const int32_t *t, int nt,
                            char *err, size_t errlen)
{
    if (err && errlen) err[0] = 0;
    try {
        return write_amf(path, v, nv, t, nt, err, errlen);
    } catch (const std::bad_alloc &) {
        if (err && errlen) std::snprintf(err, errlen, "%s: out of memory", path ? path : "AMF");
        return -1;
    } catch (...) {
        if (err && errlen) std::snprintf(err, errlen, "%s: AMF write failed", path ? path : "");
        return -1;
    }
}
