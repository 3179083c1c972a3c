/*
 * export.h — for the AMF and 3MF writers (amf.cpp, 3mf.cpp): the check
 * of the arrays before a byte is written, and a hash of them from which
 * the 3MF's UUIDs are drawn.  C++, header-only, private to src/io.
 */
#ifndef RAYSCAD_IO_EXPORT_H
#define RAYSCAD_IO_EXPORT_H

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

namespace io_export
{

/* "" when the arrays (the conventions of io.h) can be exported, else why
 * not: a negative count, missing arrays, a coordinate that is NaN or
 * infinite (no reader makes a solid of it), an index out of range, or a
 * triangle with a repeated vertex (lib3mf refuses those; the AMF writer
 * refuses them too, so both formats accept the same meshes).  Unlike the
 * OpenMesh writers, nothing asks for a 2-manifold: both formats hold any
 * triangle soup. */
inline std::string check(const float *v, int nv, const int32_t *t, int nt)
{
    if (nv < 0 || nt < 0) return "negative vertex or triangle count";
    if ((nv > 0 && !v) || (nt > 0 && !t)) return "no vertex or triangle array";
    for (size_t i = 0; i < 3 * (size_t)nv; i++)
        if (!std::isfinite(v[i]))
            return "vertex " + std::to_string(i / 3) + " has a coordinate that is not finite";
    for (size_t i = 0; i < (size_t)nt; i++) {
        const int32_t *f = t + 3 * i;
        for (int k = 0; k < 3; k++)
            if (f[k] < 0 || f[k] >= nv)
                return "triangle " + std::to_string(i) + " has an index out of range";
        if (f[0] == f[1] || f[1] == f[2] || f[2] == f[0])
            return "triangle " + std::to_string(i) + " is degenerate (a repeated vertex)";
    }
    return "";
}

/* FNV-1a (64 bits) of the arrays' bytes: equal meshes hash equal, so a
 * file written twice from one mesh is the same file. */
inline uint64_t hash(const float *v, int nv, const int32_t *t, int nt)
{
    uint64_t h = 1469598103934665603ull;
    const unsigned char *p = (const unsigned char *)v;
    for (size_t i = 0; i < 3 * sizeof(float) * (size_t)nv; i++)
        h = (h ^ p[i]) * 1099511628211ull;
    p = (const unsigned char *)t;
    for (size_t i = 0; i < 3 * sizeof(int32_t) * (size_t)nt; i++)
        h = (h ^ p[i]) * 1099511628211ull;
    return h;
}

/* splitmix64's finaliser: 64 well-mixed bits from h and a stream number k,
 * for names drawn from one hash. */
inline uint64_t mix(uint64_t h, uint64_t k)
{
    uint64_t z = h + (k + 1) * 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

} // namespace io_export

#endif
