/*
 * polygon.cpp — io_polygon_* (polygon.h) over Clipper 6.4.
 *
 * Model coordinates become Clipper's 64-bit integers at 2^16 units per
 * model unit, OpenSCAD 2021.01's CLIPPER_SCALE, so results snap to the same
 * 1/65536 grid as OpenSCAD's.  Every result goes through a PolyTree and
 * CleanPolygon at 0.001 model units (OpenSCAD's toPolygon2d), which drops
 * near-collinear and near-duplicate points; an outline left with fewer than
 * 3 points is dropped.  Invariant at this boundary: no exception crosses it
 * (each entry point catches all and returns -1 with a message), nothing
 * prints, and the caller's arrays are only read.
 */
#include "polygon.h"

#include <clipper.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <new>
#include <string>

namespace
{

using ClipperLib::cInt;
using ClipperLib::IntPoint;
using ClipperLib::Path;
using ClipperLib::Paths;

const double SCALE = 65536.0;        /* OpenSCAD 2021.01 CLIPPER_SCALE */
const double CLEAN_DISTANCE = 0.001; /* model units, OpenSCAD's toPolygon2d */
const double RANGE = 4.0e18 / SCALE; /* below Clipper's hiRange (~4.6e18) */

void set_err(char *err, size_t errlen, const char *msg)
{
    if (err && errlen) std::snprintf(err, errlen, "%s", msg);
}

/* Model paths → Clipper paths; throws std::range_error on out-of-range or
 * non-finite coordinates. */
Paths to_clipper(const io_paths *p)
{
    Paths out;
    if (!p) return out;
    for (int i = 0; i < p->npaths; i++) {
        Path q;
        for (int k = p->start[i]; k < p->start[i + 1]; k++) {
            double x = p->pts[k][0], y = p->pts[k][1];
            if (!std::isfinite(x) || !std::isfinite(y) || std::fabs(x) > RANGE ||
                std::fabs(y) > RANGE)
                throw std::range_error("polygon coordinate out of range");
            /* truncated toward zero, as openscad's IntPoint(v[0] * CLIPPER_SCALE, …)
             * converts: its exports show the grid point below, not the nearest */
            q.emplace_back((cInt)(x * SCALE), (cInt)(y * SCALE));
        }
        if (q.size() >= 3) out.push_back(q);
    }
    return out;
}

/* Paths at Clipper's scale into a malloc'ed io_paths (empty for none).
 * 0, or -1 out of memory. */
int from_paths(const Paths &all, double scale, io_paths *out)
{
    size_t total = 0;
    for (const Path &p : all)
        total += p.size();
    out->pts = nullptr;
    out->start = nullptr;
    out->npaths = 0;
    if (all.empty()) return 0;
    out->pts = static_cast<double(*)[2]>(std::malloc(total * sizeof *out->pts));
    out->start = static_cast<int *>(std::malloc((all.size() + 1) * sizeof *out->start));
    if (!out->pts || !out->start) {
        io_paths_free(out);
        return -1;
    }
    size_t k = 0;
    for (size_t i = 0; i < all.size(); i++) {
        out->start[i] = (int)k;
        for (const IntPoint &q : all[i]) {
            out->pts[k][0] = (double)q.X / scale;
            out->pts[k][1] = (double)q.Y / scale;
            k++;
        }
    }
    out->start[all.size()] = (int)k;
    out->npaths = (int)all.size();
    return 0;
}

/* A PolyTree's outlines, cleaned, into a malloc'ed io_paths. */
int from_tree(const ClipperLib::PolyTree &tree, io_paths *out)
{
    Paths all;
    for (ClipperLib::PolyNode *n = tree.GetFirst(); n; n = n->GetNext()) {
        if (n->IsOpen()) continue;
        Path c;
        ClipperLib::CleanPolygon(n->Contour, c, CLEAN_DISTANCE * SCALE);
        if (c.size() >= 3) all.push_back(c);
    }
    return from_paths(all, SCALE, out);
}

ClipperLib::PolyFillType fill(int evenodd)
{
    return evenodd ? ClipperLib::pftEvenOdd : ClipperLib::pftNonZero;
}

/* The one way out of every entry point: make(tree) fills a PolyTree (false:
 * the operation failed, and `failed` says so), which becomes *out.  Every
 * exception ends here as -1 and a message, so none crosses into C. */
template <class Make>
int run(const char *failed, io_paths *out, char *err, size_t errlen, Make make)
{
    try {
        ClipperLib::PolyTree tree;
        if (!make(tree)) {
            set_err(err, errlen, failed);
            return -1;
        }
        if (from_tree(tree, out) != 0) {
            set_err(err, errlen, "out of memory");
            return -1;
        }
        return 0;
    } catch (const std::bad_alloc &) {
        set_err(err, errlen, "out of memory");
    } catch (const std::exception &e) {
        set_err(err, errlen, e.what());
    } catch (...) {
        set_err(err, errlen, failed);
    }
    return -1;
}

} // namespace

extern "C" void io_paths_free(io_paths *p)
{
    if (!p) return;
    std::free(p->pts);
    std::free(p->start);
    p->pts = nullptr;
    p->start = nullptr;
    p->npaths = 0;
}

extern "C" int io_polygon_clip(io_clip_op op, const io_paths *a, int a_evenodd, const io_paths *b,
                               int b_evenodd, io_paths *out, char *err, size_t errlen)
{
    return run("polygon boolean failed", out, err, errlen, [&](ClipperLib::PolyTree &tree) {
        static const ClipperLib::ClipType types[] = {ClipperLib::ctUnion,
                                                     ClipperLib::ctIntersection,
                                                     ClipperLib::ctDifference, ClipperLib::ctXor};
        ClipperLib::Clipper c;
        bool any = c.AddPaths(to_clipper(a), ClipperLib::ptSubject, true);
        any = c.AddPaths(to_clipper(b), ClipperLib::ptClip, true) || any;
        /* Clipper 6.4's Execute fails on no edges at all (paths of one
         * repeated point, or that all collapse): the result is empty */
        if (!any) return true;
        return c.Execute(types[op], tree, fill(a_evenodd), fill(b_evenodd));
    });
}

extern "C" int io_polygon_offset(const io_paths *a, double delta, io_join join, double miter_limit,
                                 double arc_tolerance, io_paths *out, char *err, size_t errlen)
{
    return run("polygon offset failed", out, err, errlen, [&](ClipperLib::PolyTree &tree) {
        if (!std::isfinite(delta) || std::fabs(delta) > RANGE)
            throw std::range_error("offset out of range");
        static const ClipperLib::JoinType types[] = {ClipperLib::jtRound, ClipperLib::jtMiter,
                                                     ClipperLib::jtSquare};
        /* As OpenSCAD: ClipperOffset(miter_limit, arc_tolerance · scale);
         * Clipper takes an arc tolerance <= 0 as its default 0.25 units. */
        ClipperLib::ClipperOffset co(miter_limit, arc_tolerance * SCALE);
        co.AddPaths(to_clipper(a), types[join], ClipperLib::etClosedPolygon);
        co.Execute(tree, delta * SCALE);
        return true;
    });
}

extern "C" int io_polygon_stroke(const double (*pts)[2], int n, double width, io_cap cap,
                                 io_paths *out, char *err, size_t errlen)
{
    out->pts = nullptr;
    out->start = nullptr;
    out->npaths = 0;
    const double scale = 10000.0; /* libsvg's, not CLIPPER_SCALE */
    try {
        Path line;
        for (int i = 0; i < n; i++) {
            double x = pts[i][0] * scale, y = pts[i][1] * scale;
            if (!std::isfinite(x) || !std::isfinite(y) || std::fabs(x) > 4.0e18 ||
                std::fabs(y) > 4.0e18)
                throw std::range_error("stroke coordinate out of range");
            /* libsvg truncates toward zero (IntPoint of a double) */
            line.emplace_back((cInt)x, (cInt)y);
        }
        if (!std::isfinite(width) || std::fabs(width * scale) > 4.0e18)
            throw std::range_error("stroke width out of range");
        static const ClipperLib::EndType ends[] = {ClipperLib::etOpenButt, ClipperLib::etOpenRound,
                                                   ClipperLib::etOpenSquare};
        ClipperLib::ClipperOffset co;
        co.AddPath(line, ClipperLib::jtMiter, ends[cap]);
        Paths result;
        co.Execute(result, width * scale / 2);
        if (from_paths(result, scale, out) == 0) return 0;
        set_err(err, errlen, "out of memory");
        return -1;
    } catch (const std::bad_alloc &) {
        set_err(err, errlen, "out of memory");
    } catch (const std::exception &e) {
        set_err(err, errlen, e.what());
    } catch (...) {
        set_err(err, errlen, "stroke failed");
    }
    io_paths_free(out);
    return -1;
}

namespace
{

/* Every edge of p swept along every edge of q: a parallelogram each, wound
 * counter-clockwise (a degenerate one, from parallel edges, is harmless to
 * the nonzero union). */
void sweep_edges(const Path &p, const Path &q, Paths &out)
{
    size_t np = p.size(), nq = q.size();
    for (size_t i = 0; i < np; i++) {
        const IntPoint &a0 = p[i], &a1 = p[(i + 1) % np];
        for (size_t j = 0; j < nq; j++) {
            const IntPoint &b0 = q[j], &b1 = q[(j + 1) % nq];
            Path quad{IntPoint(a0.X + b0.X, a0.Y + b0.Y), IntPoint(a1.X + b0.X, a1.Y + b0.Y),
                      IntPoint(a1.X + b1.X, a1.Y + b1.Y), IntPoint(a0.X + b1.X, a0.Y + b1.Y)};
            if (!ClipperLib::Orientation(quad)) ClipperLib::ReversePath(quad);
            out.push_back(quad);
        }
    }
}

/* All of a, moved to the first point of each outline (counter-clockwise
 * path) of b. */
void fill_insides(const Paths &a, const Paths &b, Paths &out)
{
    for (const Path &bp : b) {
        if (bp.empty() || !ClipperLib::Orientation(bp)) continue;
        for (const Path &ap : a) {
            Path m = ap;
            for (IntPoint &p : m) {
                p.X += bp[0].X;
                p.Y += bp[0].Y;
            }
            out.push_back(m);
        }
    }
}

} // namespace

extern "C" int io_polygon_minkowski(const io_paths *a, const io_paths *b, io_paths *out, char *err,
                                    size_t errlen)
{
    return run("Minkowski sum failed", out, err, errlen, [&](ClipperLib::PolyTree &tree) {
        Paths pa = to_clipper(a), pb = to_clipper(b), terms;
        if (pa.empty() || pb.empty()) return true; /* the empty tree: no outline */
        for (const Path &p : pa)
            for (const Path &q : pb)
                sweep_edges(p, q, terms);
        fill_insides(pa, pb, terms);
        fill_insides(pb, pa, terms);
        ClipperLib::Clipper c;
        c.AddPaths(terms, ClipperLib::ptSubject, true);
        return c.Execute(ClipperLib::ctUnion, tree, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    });
}
