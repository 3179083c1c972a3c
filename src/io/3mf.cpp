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
 * io_3mf_write writes a mesh as 2021.01's 3MF export does (its
 * src/export_3mf.cc): through lib3mf's writer, one mesh object (named
 * "rayscad Model" where 2021.01 says "OpenSCAD Model") and one build item
 * for it without a transform, unit millimetre, and also the model metadata
 * "Application" naming rayscad (2021.01 writes none).  lib3mf 1.8 prints
 * each coordinate with six decimals, cut toward zero (so do 2021.01's
 * files): each coordinate moves toward 0 by less than 1e-6 mm, and two
 * vertices closer than that may become one.  lib3mf gives
 * the object, the build and the item production-extension UUIDs, random
 * unless set; here they are derived from a hash of the arrays, so one mesh
 * always makes the same file.  lib3mf writes the package to
 * io_temp_beside's temporary file, renamed over path only when it reports
 * success.
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

#include <unistd.h>

#include "../../include/rayscad.h"
#include "export.h"
#include "io.h"
#include "temp_file.h"
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

namespace
{

/* UUID number k (8-4-4-4-12 hex digits) of a mesh of hash h, with the
 * version and variant bits of RFC 9562's version 8 (custom). */
std::string uuid_of(uint64_t h, uint64_t k)
{
    uint64_t hi = io_export::mix(h, 2 * k), lo = io_export::mix(h, 2 * k + 1);
    hi = (hi & ~(uint64_t)0xf000) | 0x8000;
    lo = (lo & ~((uint64_t)3 << 62)) | ((uint64_t)2 << 62);
    char s[40];
    std::snprintf(s, sizeof s, "%08x-%04x-%04x-%04x-%012llx", (unsigned)(hi >> 32),
                  (unsigned)(hi >> 16 & 0xffff), (unsigned)(hi & 0xffff), (unsigned)(lo >> 48),
                  (unsigned long long)(lo & 0xffffffffffffull));
    return s;
}

/* Give every triangle of mesh its colour (c may be NULL: none), and the
 * object io_default_rgba as its default.  lib3mf writes them as one colour
 * group; it reads #00000000 as "no colour", which only a fully transparent
 * black could be, and that then shows the default. */
template <typename Ok> bool colors(Held &mesh, int nt, const io_colors *c, Ok &ok)
{
    if (!c) return true;
    std::vector<NMR::MODELMESHCOLOR_SRGB> each((size_t)nt + 1);
    for (int i = 0; i < nt; i++) {
        unsigned char b[4];
        io_color_bytes(c, i, b);
        each[(size_t)i] = {b[0], b[1], b[2], b[3]};
    }
    unsigned char d[4];
    io_color_bytes(nullptr, 0, d);
    Held handler, fallback;
    return ok(NMR::lib3mf_meshobject_createpropertyhandler(mesh.p, &handler.p), "colours",
              mesh.p) &&
           ok(NMR::lib3mf_propertyhandler_setsinglecolorarray(handler.p, each.data()), "colours",
              handler.p) &&
           ok(NMR::lib3mf_object_createdefaultpropertyhandler(mesh.p, &fallback.p),
              "default colour", mesh.p) &&
           ok(NMR::lib3mf_defaultpropertyhandler_setcolorrgba(fallback.p, d[0], d[1], d[2], d[3]),
              "default colour", fallback.p);
}

int write_3mf(const char *path, const float *v, int nv, const int32_t *t, int nt,
              const io_colors *c, char *err, size_t errlen)
{
    std::string why = io_export::check(v, nv, t, nt);
    if (!why.empty()) {
        set_msg(err, errlen, std::string(path) + ": " + why);
        return -1;
    }
    std::vector<NMR::MODELMESHVERTEX> verts((size_t)nv + 1); /* never empty: data() != NULL */
    std::vector<NMR::MODELMESHTRIANGLE> tris((size_t)nt + 1);
    for (size_t i = 0; i < (size_t)nv; i++)
        for (int k = 0; k < 3; k++)
            verts[i].m_fPosition[k] = v[3 * i + (size_t)k] + 0.0f; /* +0 for -0 */
    for (size_t i = 0; i < (size_t)nt; i++)
        for (int k = 0; k < 3; k++)
            tris[i].m_nIndices[k] = (DWORD)t[3 * i + (size_t)k];
    uint64_t h = io_export::hash(v, nv, t, nt);
    std::string object_uuid = uuid_of(h, 0), build_uuid = uuid_of(h, 1), item_uuid = uuid_of(h, 2);
    std::vector<char> tmp(std::strlen(path) + 64);

    /* true when rc is success; else the message names the step and lib3mf's
     * last error on the object it was asked of */
    auto ok = [&](LIB3MFRESULT rc, const char *step, NMR::PLib3MFBase *on) {
        if (rc == LIB3MF_OK) return true;
        std::string e = last_error(on);
        set_msg(err, errlen, std::string(path) + ": lib3mf: " + step + (e.empty() ? "" : ": " + e));
        return false;
    };
    Held model, mesh, item, writer;
    const char *app = "rayscad " RAYSCAD_VERSION_STRING;
    if (!ok(NMR::lib3mf_createmodel(&model.p), "cannot create a model", nullptr) ||
        !ok(NMR::lib3mf_model_setunit(model.p, NMR::MODELUNIT_MILLIMETER), "unit", model.p) ||
        !ok(NMR::lib3mf_model_addmeshobject(model.p, &mesh.p), "mesh object", model.p) ||
        !ok(NMR::lib3mf_object_setnameutf8(mesh.p, "rayscad Model"), "object name", mesh.p) ||
        !ok(NMR::lib3mf_object_setuuidutf8(mesh.p, object_uuid.c_str()), "object UUID", mesh.p) ||
        !ok(NMR::lib3mf_meshobject_setgeometry(mesh.p, verts.data(), (DWORD)nv, tris.data(),
                                               (DWORD)nt),
            "geometry", mesh.p) ||
        !colors(mesh, nt, c, ok) ||
        !ok(NMR::lib3mf_model_addbuilditem(model.p, mesh.p, nullptr, &item.p), "build item",
            model.p) ||
        !ok(NMR::lib3mf_builditem_setuuidutf8(item.p, item_uuid.c_str()), "build item UUID",
            item.p) ||
        !ok(NMR::lib3mf_model_setbuilduuidutf8(model.p, build_uuid.c_str()), "build UUID",
            model.p) ||
        !ok(NMR::lib3mf_model_addmetadatautf8(model.p, "Application", app), "metadata", model.p) ||
        !ok(NMR::lib3mf_model_querywriter(model.p, "3mf", &writer.p), "no 3MF writer", model.p))
        return -1;
    if (io_temp_beside(path, tmp.data(), tmp.size(), err, errlen) != 0) return -1;
    if (NMR::lib3mf_writer_writetofileutf8(writer.p, tmp.data()) != LIB3MF_OK) {
        unlink(tmp.data());
        std::string e = last_error(writer.p);
        set_msg(err, errlen, std::string(path) + ": writing failed" + (e.empty() ? "" : ": " + e));
        return -1;
    }
    return io_temp_commit(tmp.data(), path, err, errlen);
}

} // namespace

extern "C" int io_3mf_write(const char *path, const float *v, int nv, const int32_t *t, int nt,
                            const io_colors *c, char *err, size_t errlen)
{
    if (err && errlen) err[0] = 0;
    try {
        return write_3mf(path, v, nv, t, nt, c, err, errlen);
    } catch (const std::bad_alloc &) {
        if (err && errlen) std::snprintf(err, errlen, "%s: out of memory", path ? path : "3MF");
        return -1;
    } catch (...) {
        if (err && errlen) std::snprintf(err, errlen, "%s: 3MF write failed", path ? path : "");
        return -1;
    }
}
