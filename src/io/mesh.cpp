/*
 * mesh.cpp — triangle meshes in and out of files through OpenMesh, behind
 * the C functions io_mesh_* of io.h.
 *
 * Our meshes are flat arrays (3 floats per vertex, 3 int32 indices per
 * triangle); each call copies them into an OpenMesh TriMesh, lets OpenMesh's
 * reader/writer/decimater work on it, and copies back.  Invariants kept at
 * this boundary: no C++ exception crosses it (every entry point catches all
 * and returns -1 with a message); nothing prints (OpenMesh's log streams are
 * disabled before each call); a written file appears complete or not at all
 * (OpenMesh writes a temporary file beside the target, with the target's
 * extension so it picks the same writer, which is renamed over the target
 * only when the writer reports success).
 */
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>
#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModNormalFlippingT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>
#include <string>
#include <vector>

#include <fcntl.h>
#include <stdlib.h>
#include <unistd.h>

#include "io.h"

namespace {

struct Traits : public OpenMesh::DefaultTraits {
    typedef OpenMesh::Vec3f Point;
    typedef OpenMesh::Vec3f Normal;
};
typedef OpenMesh::TriMesh_ArrayKernelT<Traits> TriMesh;

void set_err(char *err, size_t errlen, const std::string &msg)
{
    if (err && errlen)
        std::snprintf(err, errlen, "%s", msg.c_str());
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
    if (!dot || (slash && dot < slash))
        return "";
    std::string e(dot + 1);
    for (char &c : e)
        c = (char)std::tolower((unsigned char)c);
    return e;
}

bool known_ext(const std::string &e)
{
    return e == "stl" || e == "off" || e == "obj" || e == "ply";
}

/* Copy the arrays into m; false (and a message) when a triangle cannot be
 * added, which happens only for a non-manifold or degenerate input. */
bool build(TriMesh &m, const float *v, int nv, const int32_t *t, int nt, std::string &msg)
{
    m.reserve((size_t)nv, (size_t)nv + (size_t)nt, (size_t)nt);
    std::vector<TriMesh::VertexHandle> vh((size_t)nv);
    for (int i = 0; i < nv; i++)
        vh[(size_t)i] = m.add_vertex(TriMesh::Point(v[3 * (size_t)i], v[3 * (size_t)i + 1],
                                                    v[3 * (size_t)i + 2]));
    for (int i = 0; i < nt; i++) {
        const int32_t *f = t + 3 * (size_t)i;
        for (int k = 0; k < 3; k++)
            if (f[k] < 0 || f[k] >= nv) {
                msg = "triangle " + std::to_string(i) + " has an index out of range";
                return false;
            }
        TriMesh::FaceHandle fh = m.add_face(vh[(size_t)f[0]], vh[(size_t)f[1]], vh[(size_t)f[2]]);
        if (!fh.is_valid()) {
            msg = "triangle " + std::to_string(i) + " would make the mesh non-manifold";
            return false;
        }
    }
    return true;
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
            if (k < 3)
                tt[3 * q + (size_t)k] = h.idx();
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
                  char *err, size_t errlen)
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
        TriMesh m;
        std::string msg;
        if (!build(m, v, nv, t, nt, msg)) {
            set_err(err, errlen, std::string(path) + ": " + msg);
            return -1;
        }
        m.request_face_normals();
        m.update_face_normals();

        /* A fresh temporary name beside path, ending in the same extension. */
        std::string p(path);
        size_t slash = p.rfind('/');
        std::string dir = slash == std::string::npos ? "" : p.substr(0, slash + 1);
        std::string base = slash == std::string::npos ? p : p.substr(slash + 1);
        std::string suffix = "." + ext;
        std::vector<char> name;
        std::string pat = dir + "." + base + ".tmp-XXXXXX" + suffix;
        name.assign(pat.begin(), pat.end());
        name.push_back('\0');
        int fd = mkstemps(name.data(), (int)suffix.size());
        if (fd < 0) {
            set_err(err, errlen, std::string(path) + ": cannot create a file there: " +
                                     std::strerror(errno));
            return -1;
        }
        close(fd);
        tmp = name.data();

        OpenMesh::IO::Options opt;
        if (ext == "stl")
            opt += OpenMesh::IO::Options::FaceNormal;
        if (!ascii && (ext == "stl" || ext == "ply"))
            opt += OpenMesh::IO::Options::Binary;
        if (!OpenMesh::IO::write_mesh(m, tmp, opt, 9)) {
            unlink(tmp.c_str());
            set_err(err, errlen, std::string(path) + ": writing failed");
            return -1;
        }
        if (rename(tmp.c_str(), path) != 0) {
            int e = errno;
            unlink(tmp.c_str());
            set_err(err, errlen, std::string(path) + ": " + std::strerror(e));
            return -1;
        }
        return 0;
    } catch (const std::bad_alloc &) {
        if (!tmp.empty())
            unlink(tmp.c_str());
        set_err(err, errlen, std::string(path ? path : "") + ": out of memory");
        return -1;
    } catch (const std::exception &e) {
        if (!tmp.empty())
            unlink(tmp.c_str());
        set_err(err, errlen, std::string(path ? path : "") + ": " + e.what());
        return -1;
    } catch (...) {
        if (!tmp.empty())
            unlink(tmp.c_str());
        set_err(err, errlen, "mesh write failed");
        return -1;
    }
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
        set_err(err, errlen, std::string(path ? path : "") + ": out of memory");
        return -1;
    } catch (const std::exception &e) {
        set_err(err, errlen, std::string(path ? path : "") + ": " + e.what());
        return -1;
    } catch (...) {
        set_err(err, errlen, "mesh read failed");
        return -1;
    }
}

int io_mesh_decimate(const float *v, int nv, const int32_t *t, int nt, double tol,
                     float **out_v, int *out_nv, int32_t **out_t, int *out_nt, char *err,
                     size_t errlen)
{
    try {
        quiet();
        *out_v = nullptr;
        *out_t = nullptr;
        *out_nv = *out_nt = 0;
        if (!(tol >= 0)) {
            set_err(err, errlen, "decimation tolerance must be >= 0");
            return -1;
        }
        TriMesh m;
        std::string msg;
        if (!build(m, v, nv, t, nt, msg)) {
            set_err(err, errlen, "decimate: " + msg);
            return -1;
        }
        typedef OpenMesh::Decimater::DecimaterT<TriMesh> Decimater;
        typedef OpenMesh::Decimater::ModQuadricT<TriMesh>::Handle Quadric;
        typedef OpenMesh::Decimater::ModNormalFlippingT<TriMesh>::Handle Flipping;
        m.request_face_normals();
        m.update_face_normals();
        /* Held here too, so they outlive the decimater (which releases its
         * own requests) until garbage_collection has used them. */
        m.request_vertex_status();
        m.request_edge_status();
        m.request_halfedge_status();
        m.request_face_status();
        {
            Decimater dec(m);
            Quadric q;
            Flipping f;
            dec.add(q);
            dec.add(f);
            /* The quadric error is a squared distance. */
            dec.module(q).set_max_err(tol * tol);
            dec.module(f).set_max_normal_deviation(60.0);
            if (!dec.initialize()) {
                set_err(err, errlen, "decimate: the decimater did not initialise");
                return -1;
            }
            dec.decimate();
        }
        m.garbage_collection();
        if (!extract(m, out_v, out_nv, out_t, out_nt, msg)) {
            set_err(err, errlen, "decimate: " + msg);
            return -1;
        }
        return 0;
    } catch (const std::bad_alloc &) {
        set_err(err, errlen, "decimate: out of memory");
        return -1;
    } catch (const std::exception &e) {
        set_err(err, errlen, std::string("decimate: ") + e.what());
        return -1;
    } catch (...) {
        set_err(err, errlen, "decimate failed");
        return -1;
    }
}

} // extern "C"
