/*
 * weld.h — one object of an imported AMF or 3MF file appended to the mesh
 * being built, its vertices welded: positions that are equal as floats
 * become one vertex (-0 and +0 alike), vertices no triangle uses are
 * dropped, and so are triangles that weld two corners into one (no area).  Tools that convert STL
 * to AMF (Cura) write each triangle's corners as vertices of their own; OpenSCAD merges them when
 * it turns the triangles into a polyhedron, and welding here does the same, so a closed surface is
 * seen closed.  Objects are never welded to each other: each stays a closed shell.  C++, private to
 * src/io.
 */
#ifndef RAYSCAD_IO_WELD_H
#define RAYSCAD_IO_WELD_H

#include <cstdint>
#include <cstring>
#include <unordered_map>
#include <vector>

namespace io_weld
{

struct Key {
    uint32_t b[3];
    bool operator==(const Key &o) const
    {
        return b[0] == o.b[0] && b[1] == o.b[1] && b[2] == o.b[2];
    }
};

struct KeyHash {
    size_t operator()(const Key &k) const
    {
        uint64_t h = 1469598103934665603ull;
        for (uint32_t x : k.b)
            h = (h ^ x) * 1099511628211ull;
        return (size_t)h;
    }
};

/* Append the triangles tris (3 indices each, into the 3-per-vertex xyz,
 * all in range) to out_t, and the vertices they use to out_v, welded.
 * False when the result would pass 2^31 vertices or triangles. */
template <typename Coord, typename Index>
bool append(const std::vector<Coord> &xyz, const std::vector<Index> &tris,
            std::vector<float> &out_v, std::vector<int32_t> &out_t)
{
    if (out_t.size() / 3 + tris.size() / 3 > (size_t)INT32_MAX) return false;
    std::vector<int32_t> remap(xyz.size() / 3, -1);
    std::unordered_map<Key, int32_t, KeyHash> seen;
    for (size_t q = 0; q < tris.size(); q++) {
        Index i = tris[q];
        int32_t &m = remap[(size_t)i];
        if (m < 0) {
            float p[3];
            Key k;
            for (int c = 0; c < 3; c++) {
                p[c] = (float)xyz[3 * (size_t)i + (size_t)c];
                if (p[c] == 0) p[c] = 0; /* -0 welds with +0 */
                std::memcpy(&k.b[c], &p[c], sizeof(float));
            }
            auto it = seen.find(k);
            if (it != seen.end()) {
                m = it->second;
            } else {
                if (out_v.size() / 3 >= (size_t)INT32_MAX) return false;
                m = (int32_t)(out_v.size() / 3);
                seen.emplace(k, m);
                out_v.insert(out_v.end(), p, p + 3);
            }
        }
        out_t.push_back(m);
        /* a triangle welded to a repeated corner has no area: dropped */
        if (q % 3 == 2) {
            int32_t *f = out_t.data() + out_t.size() - 3;
            if (f[0] == f[1] || f[1] == f[2] || f[2] == f[0]) out_t.resize(out_t.size() - 3);
        }
    }
    return true;
}

} // namespace io_weld

#endif
