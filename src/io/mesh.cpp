/*
 * mesh.cpp — triangle meshes in and out of files through OpenMesh, behind
 * the C functions io_mesh_* of io.h.
 *
 * Our meshes are flat arrays (3 floats per vertex, 3 int32 indices per
 * triangle); each call copies them into an OpenMesh TriMesh, lets OpenMesh's
 * reader or writer work on it, and copies back.  Invariants kept at
 * this boundary: no C++ exception crosses it (every entry point catches all
 * and returns -1 with a message); nothing prints (OpenMesh's log streams are
 * disabled before each call); a written file appears complete or not at all
 * (OpenMesh writes to io_temp_beside's temporary file, which keeps the
 * target's extension so OpenMesh picks the same writer, and io_temp_commit
 * renames it over the target only when the writer reports success).
 *
 * Building the TriMesh: a closed, consistently oriented, 2-manifold input
 * (what mesh_dexels_contour makes) is built directly: each directed edge
 * finds its twin in a per-vertex table, and the kernel's arrays are sized
 * once and filled (next, face and vertex handles), then checked (every
 * directed edge once, its reverse once, every vertex's triangles one fan).
 * That is what add_face would build, without its per-face search around
 * each vertex and growing arrays: 6× faster on 270k triangles.  Anything
 * else (open meshes) goes through add_face, which rejects what OpenMesh
 * cannot hold.  Face normals for STL are computed here, in double, from the
 * arrays rather than by OpenMesh's face circulators.
 */
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>
#include <string>
#include <vector>

#include <unistd.h>

#include "io.h"
#include "temp_file.h"

namespace
{

struct Traits : public OpenMesh::DefaultTraits {
    typedef OpenMesh::Vec3f Point;
    typedef OpenMesh::Vec3f Normal;
    typedef OpenMesh::Vec4uc Color; /* PLY's face colours, with alpha */
};
typedef OpenMesh::TriMesh_ArrayKernelT<Traits> TriMesh;

void set_err(char *err, size_t errlen, const std::string &msg)
{
    if (err && errlen) std::snprintf(err, errlen, "%s", msg.c_str());
}

void quiet()
{
    omlog().disable();
    omout().disable();
    omerr().disable();
}

std::string lower_ext(const char *path)
{
    const char *slash = std::strrchr(path, '/');
    const char *dot = std::strrchr(path, '.');
    if (!dot || (slash && dot < slash)) return "";
    std::string e(dot + 1);
    for (char &c : e)
        c = (char)std::tolower((unsigned char)c);
    return e;
}

bool known_ext(const std::string &e)
{
    return e == "stl" || e == "off" || e == "obj" || e == "ply";
}

bool indices_ok(const int32_t *t, int nv, int nt, std::string &msg)
{
    for (int i = 0; i < nt; i++) {
        const int32_t *f = t + 3 * (size_t)i;
        for (int k = 0; k < 3; k++)
            if (f[k] < 0 || f[k] >= nv) {
                msg = "triangle " + std::to_string(i) + " has an index out of range";
                return false;
            }
    }
    return true;
}

/* The general path: add_face, which refuses a face that would make the
 * mesh non-manifold. */
bool build_by_faces(TriMesh &m, const float *v, int nv, const int32_t *t, int nt, std::string &msg)
{
    m.reserve((size_t)nv, (size_t)nv + (size_t)nt, (size_t)nt);
    std::vector<TriMesh::VertexHandle> vh((size_t)nv);
    for (int i = 0; i < nv; i++)
        vh[(size_t)i] = m.add_vertex(
            TriMesh::Point(v[3 * (size_t)i], v[3 * (size_t)i + 1], v[3 * (size_t)i + 2]));
    for (int i = 0; i < nt; i++) {
        const int32_t *f = t + 3 * (size_t)i;
        TriMesh::FaceHandle fh = m.add_face(vh[(size_t)f[0]], vh[(size_t)f[1]], vh[(size_t)f[2]]);
        if (!fh.is_valid()) {
            msg = "triangle " + std::to_string(i) + " would make the mesh non-manifold";
            return false;
        }
    }
    return true;
}

/* Corner q of triangle q / 3 starts the directed edge t[q] -> t[next(q)]. */
inline size_t next_corner(size_t q)
{
    return q % 3 == 2 ? q - 2 : q + 1;
}

/* The direct path for closed manifold input.  Returns 1 when m is built, 0
 * when the input is not closed (some directed edge has no reverse; m is
 * untouched), -1 with a message when it is closed but not a 2-manifold. */
int build_closed(TriMesh &m, const float *v, int nv, const int32_t *t, int nt, std::string &msg)
{
    size_t nc = 3 * (size_t)nt;
    /* Corners grouped by their start vertex (CSR). */
    std::vector<int32_t> first((size_t)nv + 1, 0);
    for (size_t q = 0; q < nc; q++) {
        if (t[q] == t[next_corner(q)]) {
            msg = "triangle " + std::to_string(q / 3) + " is degenerate (a repeated vertex)";
            return -1;
        }
        first[(size_t)t[q] + 1]++;
    }
    for (int i = 0; i < nv; i++)
        first[(size_t)i + 1] += first[(size_t)i];
    /* Each entry holds the edge's end vertex too, so the twin search reads
     * one contiguous run instead of the scattered triangles. */
    struct out_edge {
        int32_t end, corner;
    };
    std::vector<out_edge> by_start(nc);
    std::vector<int32_t> fill(first.begin(), first.end() - 1);
    for (size_t q = 0; q < nc; q++)
        by_start[(size_t)fill[(size_t)t[q]]++] = {t[next_corner(q)], (int32_t)q};

    /* Pair each directed edge with its reverse: halfedges 2e and 2e + 1. */
    std::vector<int32_t> he(nc, -1);
    int32_t ne = 0;
    for (size_t q = 0; q < nc; q++) {
        if (he[q] >= 0) continue;
        int32_t a = t[q], b = t[next_corner(q)];
        int twins = 0, same = 0;
        size_t twin = 0;
        for (int32_t k = first[(size_t)b]; k < first[(size_t)b + 1]; k++)
            if (by_start[(size_t)k].end == a) {
                twin = (size_t)by_start[(size_t)k].corner;
                twins++;
            }
        for (int32_t k = first[(size_t)a]; k < first[(size_t)a + 1]; k++)
            same += by_start[(size_t)k].end == b;
        if (twins == 0) return 0;
        if (twins > 1 || same > 1 || he[twin] >= 0) {
            msg = "triangle " + std::to_string(q / 3) +
                  " would make the mesh non-manifold (an edge in more than two triangles, or "
                  "two triangles that disagree on orientation)";
            return -1;
        }
        he[q] = 2 * ne;
        he[twin] = 2 * ne + 1;
        ne++;
    }

    m.resize((size_t)nv, (size_t)ne, (size_t)nt);
    for (int i = 0; i < nv; i++)
        m.set_point(TriMesh::VertexHandle(i),
                    TriMesh::Point(v[3 * (size_t)i], v[3 * (size_t)i + 1], v[3 * (size_t)i + 2]));
    for (size_t q = 0; q < nc; q++) {
        TriMesh::HalfedgeHandle h(he[q]);
        TriMesh::FaceHandle f((int)(q / 3));
        m.set_vertex_handle(h, TriMesh::VertexHandle(t[next_corner(q)]));
        m.set_face_handle(h, f);
        m.set_next_halfedge_handle(h, TriMesh::HalfedgeHandle(he[next_corner(q)]));
        m.set_halfedge_handle(TriMesh::VertexHandle(t[q]), h);
        /* The face's halfedge ends at its first vertex, so OpenMesh lists
         * the vertices in the input's order (as add_face does). */
        if (q % 3 == 2) m.set_halfedge_handle(f, h);
    }
    /* Each vertex's outgoing halfedges must form one cycle under
     * next(opposite(h)); two fans at one vertex (a pinch) would not. */
    for (int i = 0; i < nv; i++) {
        int32_t valence = first[(size_t)i + 1] - first[(size_t)i];
        if (valence == 0) continue;
        TriMesh::HalfedgeHandle h0 = m.halfedge_handle(TriMesh::VertexHandle(i)), h = h0;
        int32_t steps = 0;
        do {
            h = m.next_halfedge_handle(m.opposite_halfedge_handle(h));
            steps++;
        } while (h != h0 && steps <= valence);
        if (steps != valence) {
            m.clear();
            msg = "vertex " + std::to_string(i) +
                  " is non-manifold (its triangles form more than one fan)";
            return -1;
        }
    }
    return 1;
}

/* Copy the arrays into m; false (and a message) when the input cannot be a
 * mesh: an index out of range, a non-manifold or degenerate triangle. */
bool build(TriMesh &m, const float *v, int nv, const int32_t *t, int nt, std::string &msg)
{
    if (!indices_ok(t, nv, nt, msg)) return false;
    int rc = build_closed(m, v, nv, t, nt, msg);
    if (rc < 0) return false;
    return rc > 0 || build_by_faces(m, v, nv, t, nt, msg);
}

/* Unit face normals, computed in double from the arrays (faces of m are
 * the triangles in order). */
/* The unit normal of triangle i (zero for a degenerate one), in double
 * from the float vertices. */
void face_normal(const float *v, const int32_t *t, int i, float out[3])
{
    const float *p0 = v + 3 * (size_t)t[3 * (size_t)i], *p1 = v + 3 * (size_t)t[3 * (size_t)i + 1],
                *p2 = v + 3 * (size_t)t[3 * (size_t)i + 2];
    double e1[3], e2[3];
    for (int k = 0; k < 3; k++) {
        e1[k] = (double)p1[k] - p0[k];
        e2[k] = (double)p2[k] - p0[k];
    }
    double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                   e1[0] * e2[1] - e1[1] * e2[0]};
    double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    double s = len > 0 ? 1 / len : 0;
    for (int k = 0; k < 3; k++)
        out[k] = (float)(n[k] * s);
}

void set_face_normals(TriMesh &m, const float *v, const int32_t *t, int nt)
{
    m.request_face_normals();
    for (int i = 0; i < nt; i++) {
        float n[3];
        face_normal(v, t, i, n);
        m.set_normal(TriMesh::FaceHandle(i), TriMesh::Normal(n[0], n[1], n[2]));
    }
}

/* Copy m (garbage-collected) out into malloc'ed arrays. */
bool extract(TriMesh &m, float **v, int *nv, int32_t **t, int *nt, std::string &msg)
{
    size_t n_v = m.n_vertices(), n_f = m.n_faces();
    if (n_v > (size_t)INT32_MAX || n_f > (size_t)INT32_MAX) {
        msg = "mesh larger than 2^31 vertices or triangles";
        return false;
    }
    float *vv = (float *)std::malloc((n_v ? n_v : 1) * 3 * sizeof(float));
    int32_t *tt = (int32_t *)std::malloc((n_f ? n_f : 1) * 3 * sizeof(int32_t));
    if (!vv || !tt) {
        std::free(vv);
        std::free(tt);
        msg = "out of memory";
        return false;
    }
    for (TriMesh::VertexHandle h : m.vertices()) {
        const TriMesh::Point &p = m.point(h);
        for (int k = 0; k < 3; k++)
            vv[3 * (size_t)h.idx() + (size_t)k] = p[k];
    }
    size_t q = 0;
    for (TriMesh::FaceHandle f : m.faces()) {
        int k = 0;
        for (TriMesh::VertexHandle h : m.fv_range(f)) {
            if (k < 3) tt[3 * q + (size_t)k] = h.idx();
            k++;
        }
        if (k != 3) {
            std::free(vv);
            std::free(tt);
            msg = "a face that is not a triangle";
            return false;
        }
        q++;
    }
    *v = vv;
    *t = tt;
    *nv = (int)n_v;
    *nt = (int)n_f;
    return true;
}

/* Text STL as openscad 2021.01 lays it out, numbers in their shortest
 * round-trip form (std::to_chars).  Not OpenMesh's writer: that one spends
 * 9 s on the 2.1 million triangles of a corpus mesh (stream formatting of
 * each number) where this takes about 1 s.  Returns false when the file
 * cannot be written. */
bool write_text_stl(const std::string &path, const float *v, const int32_t *t, int nt)
{
    FILE *f = std::fopen(path.c_str(), "wb");
    if (!f) return false;
    std::vector<char> buf(1 << 20);
    size_t used = 0;
    auto put = [&](const char *s, size_t n) {
        if (used + n > buf.size()) {
            std::fwrite(buf.data(), 1, used, f);
            used = 0;
        }
        std::memcpy(buf.data() + used, s, n);
        used += n;
    };
    auto puts_ = [&](const char *s) { put(s, std::strlen(s)); };
    auto num = [&](float x) {
        char s[32];
        auto r = std::to_chars(s, s + sizeof s, x == 0 ? 0.0f : x); /* no "-0" */
        put(" ", 1);
        put(s, (size_t)(r.ptr - s));
    };
    puts_("solid rayscad\n");
    for (int i = 0; i < nt; i++) {
        const float *p[3];
        for (int k = 0; k < 3; k++)
            p[k] = v + 3 * (size_t)t[3 * (size_t)i + (size_t)k];
        float n[3];
        face_normal(v, t, i, n);
        puts_("  facet normal");
        for (int k = 0; k < 3; k++)
            num(n[k]);
        puts_("\n    outer loop\n");
        for (int c = 0; c < 3; c++) {
            puts_("      vertex");
            for (int k = 0; k < 3; k++)
                num(p[c][k]);
            puts_("\n");
        }
        puts_("    endloop\n  endfacet\n");
    }
    puts_("endsolid rayscad\n");
    std::fwrite(buf.data(), 1, used, f);
    bool ok = !std::ferror(f);
    return std::fclose(f) == 0 && ok;
}

} // namespace

extern "C" {

int io_mesh_format_supported(const char *path)
{
    try {
        return path && known_ext(lower_ext(path)) ? 1 : 0;
    } catch (...) {
        return 0;
    }
}

int io_mesh_write(const char *path, const float *v, int nv, const int32_t *t, int nt, int ascii,
                  const io_colors *c, char *err, size_t errlen)
{
    std::string tmp;
    try {
        quiet();
        std::string ext = lower_ext(path);
        if (!known_ext(ext)) {
            set_err(err, errlen,
                    std::string(path) + ": unknown mesh format (use .stl, .off, .obj or .ply)");
            return -1;
        }
        if (c && ext == "obj") return io_obj_write(path, v, nv, t, nt, c, err, errlen);
        TriMesh m;
        std::string msg;
        if (!build(m, v, nv, t, nt, msg)) {
            set_err(err, errlen, std::string(path) + ": " + msg);
            return -1;
        }
        OpenMesh::IO::Options opt;
        bool text_stl = ascii && ext == "stl"; /* write_text_stl: normals of its own */
        if (ext == "stl" && !text_stl) {
            set_face_normals(m, v, t, nt);
            opt += OpenMesh::IO::Options::FaceNormal;
        }
        if (!ascii && (ext == "stl" || ext == "ply")) opt += OpenMesh::IO::Options::Binary;
        if (c && ext == "ply") {
            m.request_face_colors();
            for (int i = 0; i < nt; i++) {
                unsigned char b[4];
                io_color_bytes(c, i, b);
                m.set_color(TriMesh::FaceHandle(i), TriMesh::Color(b[0], b[1], b[2], b[3]));
            }
            opt += OpenMesh::IO::Options::FaceColor;
            opt += OpenMesh::IO::Options::ColorAlpha;
        }

        std::vector<char> name(std::strlen(path) + 64);
        if (io_temp_beside(path, name.data(), name.size(), err, errlen) != 0) return -1;
        tmp = name.data();
        if (text_stl ? !write_text_stl(tmp, v, t, nt) : !OpenMesh::IO::write_mesh(m, tmp, opt, 9)) {
            unlink(tmp.c_str());
            set_err(err, errlen, std::string(path) + ": writing failed");
            return -1;
        }
        std::string done;
        done.swap(tmp); /* io_temp_commit removes it on failure */
        if (io_temp_commit(done.c_str(), path, err, errlen) != 0) return -1;
        return 0;
    } catch (const std::bad_alloc &) {
        if (!tmp.empty()) unlink(tmp.c_str());
        /* No std::string here: an allocation could throw again. */
        if (err && errlen) std::snprintf(err, errlen, "%s: out of memory", path ? path : "mesh");
        return -1;
    } catch (const std::exception &e) {
        if (!tmp.empty()) unlink(tmp.c_str());
        set_err(err, errlen, std::string(path ? path : "") + ": " + e.what());
        return -1;
    } catch (...) {
        if (!tmp.empty()) unlink(tmp.c_str());
        set_err(err, errlen, "mesh write failed");
        return -1;
    }
}

/* OFF and PLY headers state element counts, and OpenMesh reserves memory
 * for them before reading a single element: a hostile header asking for
 * 2e9 vertices would take tens of GB.  Every element needs a few bytes of
 * the file (a text vertex "0 0 0\n" six, a binary one twelve), so counts
 * that the file's size cannot hold are refused up front.  True when the
 * header is plausible (or there is none to check). */
static bool plausible_counts(const char *path, const std::string &ext, std::string &msg)
{
    if (ext != "off" && ext != "ply") return true;
    std::FILE *f = std::fopen(path, "rb");
    if (!f) return true; /* the reader reports it */
    std::fseek(f, 0, SEEK_END);
    long size = std::ftell(f);
    std::fseek(f, 0, SEEK_SET);
    double need = 0;
    char line[512];
    if (ext == "off") {
        /* "OFF" (any prefix letters), comments, then "nv nf ne" */
        std::string words;
        while (std::fgets(line, sizeof line, f) && words.size() < 4096) {
            if (line[0] == '#') continue;
            words += line;
            words += ' ';
            double a, b;
            const char *p = words.c_str();
            while (*p && !std::isdigit((unsigned char)*p) && *p != '-')
                p++;
            if (std::sscanf(p, "%lf %lf", &a, &b) == 2) {
                need = 6 * a + 8 * b;
                break;
            }
        }
    } else {
        while (std::fgets(line, sizeof line, f) && std::strncmp(line, "end_header", 10) != 0) {
            char kind[64];
            double n;
            if (std::sscanf(line, "element %63s %lf", kind, &n) == 2) need += 3 * n;
        }
    }
    std::fclose(f);
    if (!(need <= (double)size)) {
        msg = "the header's element counts need more than the file's " + std::to_string(size) +
              " bytes";
        return false;
    }
    return true;
}

int io_mesh_read(const char *path, float **v, int *nv, int32_t **t, int *nt, char *err,
                 size_t errlen)
{
    try {
        quiet();
        *v = nullptr;
        *t = nullptr;
        *nv = *nt = 0;
        std::string ext = lower_ext(path);
        if (!known_ext(ext)) {
            set_err(err, errlen, std::string(path) + ": unknown mesh format");
            return -1;
        }
        if (access(path, R_OK) != 0) {
            set_err(err, errlen, std::string(path) + ": " + std::strerror(errno));
            return -1;
        }
        std::string why;
        if (!plausible_counts(path, ext, why)) {
            set_err(err, errlen, std::string(path) + ": " + why);
            return -1;
        }
        TriMesh m;
        OpenMesh::IO::Options opt;
        if (!OpenMesh::IO::read_mesh(m, path, opt)) {
            set_err(err, errlen, std::string(path) + ": cannot read it as a mesh");
            return -1;
        }
        std::string msg;
        if (!extract(m, v, nv, t, nt, msg)) {
            set_err(err, errlen, std::string(path) + ": " + msg);
            return -1;
        }
        return 0;
    } catch (const std::bad_alloc &) {
        /* No std::string here: an allocation could throw again. */
        if (err && errlen) std::snprintf(err, errlen, "%s: out of memory", path ? path : "mesh");
        return -1;
    } catch (const std::exception &e) {
        set_err(err, errlen, std::string(path ? path : "") + ": " + e.what());
        return -1;
    } catch (...) {
        set_err(err, errlen, "mesh read failed");
        return -1;
    }
}

} // extern "C"
