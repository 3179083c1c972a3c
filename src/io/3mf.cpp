/*
 * 3mf.cpp — import() of 3MF files as OpenSCAD 2021.01 reads them (its
 * src/import_3mf.cc, lib3mf 1.x API), behind io_3mf_read of io.h.
 *
 * lib3mf 1.8.1 (the version Debian's openscad 2021.01 links) reads the
 * whole package; then every mesh object resource of the model is taken, in
 * the model's order, with its vertices as stored: like 2021.01, the build
 * items and their transforms, components objects, units, colors and
 * materials are not looked at.  OpenSCAD unions the objects (CGAL); here
 * they are concatenated into one mesh, which is their union under the
 * nonzero winding rule of iv_shape_mesh and of the mesher, each object's
 * vertices welded (weld.h).  A triangle
 * index out of its object's vertices is refused (lib3mf checks this when
 * reading already).
 *
 * lib3mf's C interface returns status codes and never throws; its objects
 * are reference counted and each one it hands out is released here.  No
 * C++ exception crosses the C boundary.
 */
#include <Model/COM/NMR_DLLInterfaces.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>
#include <string>
#include <vector>

#include "io.h"
#include "weld.h"

namespace
{

void set_msg(char *msg, size_t msglen, const std::string &s)
{
    if (msg && msglen) std::snprintf(msg, msglen, "%s", s.c_str());
}

/* Releases a lib3mf object when it goes out of scope. */
struct Held {
    NMR::PLib3MFBase *p = nullptr;
    Held() = default;
    Held(const Held &) = delete;
    Held &operator=(const Held &) = delete;
    ~Held()
    {
        if (p) NMR::lib3mf_release(p);
    }
};

/* lib3mf's last error on object p, or "". */
std::string last_error(NMR::PLib3MFBase *p)
{
    DWORD code = 0;
    LPCSTR text = nullptr;
    if (!p || NMR::lib3mf_getlasterror(p, &code, &text) != LIB3MF_OK) return "";
    std::string s = text && *text ? text : "";
    char hex[32];
    std::snprintf(hex, sizeof hex, "lib3mf error 0x%08x", (unsigned)code);
    return s.empty() ? std::string(hex) : s + " (" + hex + ")";
}

int read_3mf(const char *path, float **v, int *nv, int32_t **t, int *nt, char *msg, size_t msglen)
{
    std::string cannot = "Could not read file '" + std::string(path) + "'";
    Held model, reader, objects;
    if (NMR::lib3mf_createmodel(&model.p) != LIB3MF_OK) {
        set_msg(msg, msglen, cannot + ": lib3mf could not create a model");
        return -1;
    }
    if (NMR::lib3mf_model_queryreader(model.p, "3mf", &reader.p) != LIB3MF_OK) {
        set_msg(msg, msglen, cannot + ": lib3mf has no 3MF reader");
        return -1;
    }
    if (NMR::lib3mf_reader_readfromfileutf8(reader.p, path) != LIB3MF_OK) {
        std::string why = last_error(reader.p);
        set_msg(msg, msglen, cannot + (why.empty() ? "" : ": " + why));
        return -1;
    }
    if (NMR::lib3mf_model_getmeshobjects(model.p, &objects.p) != LIB3MF_OK) {
        set_msg(msg, msglen, cannot + ": " + last_error(model.p));
        return -1;
    }
    std::vector<float> out_v;
    std::vector<int32_t> out_t;
    std::vector<NMR::MODELMESHVERTEX> verts;
    std::vector<NMR::MODELMESHTRIANGLE> tris;
    std::vector<float> xyz;
    std::vector<DWORD> idx;
    for (int object = 0;; object++) {
        int more = 0;
        if (NMR::lib3mf_resourceiterator_movenext(objects.p, &more) != LIB3MF_OK) {
            set_msg(msg, msglen, cannot + ": " + last_error(objects.p));
            return -1;
        }
        if (!more) break;
        Held mesh;
        DWORD n_v = 0, n_t = 0;
        if (NMR::lib3mf_resourceiterator_getcurrent(objects.p, &mesh.p) != LIB3MF_OK ||
            NMR::lib3mf_meshobject_getvertexcount(mesh.p, &n_v) != LIB3MF_OK ||
            NMR::lib3mf_meshobject_gettrianglecount(mesh.p, &n_t) != LIB3MF_OK) {
            set_msg(msg, msglen,
                    cannot + ": mesh object " + std::to_string(object) + ": " +
                        last_error(mesh.p ? mesh.p : objects.p));
            return -1;
        }
        if (n_t == 0) continue;
        verts.resize(n_v ? n_v : 1);
        tris.resize(n_t);
        if ((n_v &&
             NMR::lib3mf_meshobject_getvertices(mesh.p, verts.data(), n_v, nullptr) != LIB3MF_OK) ||
            NMR::lib3mf_meshobject_gettriangleindices(mesh.p, tris.data(), n_t, nullptr) !=
                LIB3MF_OK) {
            set_msg(msg, msglen,
                    cannot + ": mesh object " + std::to_string(object) + ": " + last_error(mesh.p));
            return -1;
        }
        xyz.clear();
        for (DWORD i = 0; i < n_v; i++)
            xyz.insert(xyz.end(), verts[i].m_fPosition, verts[i].m_fPosition + 3);
        idx.clear();
        for (DWORD i = 0; i < n_t; i++)
            for (int k = 0; k < 3; k++) {
                DWORD j = tris[i].m_nIndices[k];
                if (j >= n_v) {
                    set_msg(msg, msglen,
                            cannot + ": mesh object " + std::to_string(object) + ": triangle " +
                                std::to_string(i) + " has an index out of range");
                    return -1;
                }
                idx.push_back(j);
            }
        if (!io_weld::append(xyz, idx, out_v, out_t)) {
            set_msg(msg, msglen, cannot + ": more than 2^31 vertices or triangles");
            return -1;
        }
    }
    if (out_t.empty()) return 0;
    float *vv = (float *)std::malloc(out_v.size() * sizeof(float));
    int32_t *tt = (int32_t *)std::malloc(out_t.size() * sizeof(int32_t));
    if (!vv || !tt) {
        std::free(vv);
        std::free(tt);
        set_msg(msg, msglen, std::string(path) + ": out of memory");
        return -1;
    }
    std::memcpy(vv, out_v.data(), out_v.size() * sizeof(float));
    std::memcpy(tt, out_t.data(), out_t.size() * sizeof(int32_t));
    *v = vv;
    *t = tt;
    *nv = (int)(out_v.size() / 3);
    *nt = (int)(out_t.size() / 3);
    return 0;
}

} // namespace

extern "C" int io_3mf_read(const char *path, float **v, int *nv, int32_t **t, int *nt, char *msg,
                           size_t msglen)
{
    if (msg && msglen) msg[0] = 0;
    *v = nullptr;
    *t = nullptr;
    *nv = *nt = 0;
    try {
        return read_3mf(path, v, nv, t, nt, msg, msglen);
    } catch (const std::bad_alloc &) {
        if (msg && msglen) std::snprintf(msg, msglen, "%s: out of memory", path ? path : "3MF");
        return -1;
    } catch (const std::exception &e) {
        if (msg && msglen) std::snprintf(msg, msglen, "%s: %s", path ? path : "3MF", e.what());
        return -1;
    } catch (...) {
        if (msg && msglen) std::snprintf(msg, msglen, "%s: 3MF read failed", path ? path : "");
        return -1;
    }
}
