/*
 * affine.c — 3×4 row-major affine maps: composition, inverse, application.
 *
 * A csg_affine m maps x to L x + t with L = rows m[0..2], m[4..6], m[8..10]
 * and t = (m[3], m[7], m[11]).  The functions here keep no state; the only
 * judgement call is what counts as singular (see csg_affine_invert).
 */
#include "csg.h"

#include <math.h>
#include <string.h>

const csg_affine csg_affine_identity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};

void csg_affine_mul(const csg_affine a, const csg_affine b, csg_affine out)
{
    double r[12];
    for (int i = 0; i < 3; i++) {
        const double *ai = a + 4 * i;
        for (int j = 0; j < 4; j++)
            r[4 * i + j] = ai[0] * b[j] + ai[1] * b[4 + j] + ai[2] * b[8 + j];
        r[4 * i + 3] += ai[3];
    }
    memcpy(out, r, sizeof r);
}

int csg_affine_invert(const csg_affine m, csg_affine out)
{
    for (int i = 0; i < 12; i++)
        if (!isfinite(m[i])) return -1;
    const double a = m[0], b = m[1], c = m[2];
    const double d = m[4], e = m[5], f = m[6];
    const double g = m[8], h = m[9], k = m[10];
    /* Cofactors of L; row i of the inverse is column i of the cofactors. */
    const double A = e * k - f * h, B = f * g - d * k, C = d * h - e * g;
    const double det = a * A + b * B + c * C;
    /* Singular "relative to the scale of m": Hadamard's inequality bounds
     * |det| by the product of the row lengths, with equality for orthogonal
     * rows.  The ratio is 1 for any rotation with non-uniform scale however
     * small, and tends to 0 only as the rows become dependent (a flattening
     * like scale([1, 1, 0]) gives exactly 0).  1e-12 leaves an inverse whose
     * rounding error is still well below single-precision pixels. */
    const double r0 = sqrt(a * a + b * b + c * c), r1 = sqrt(d * d + e * e + f * f),
                 r2 = sqrt(g * g + h * h + k * k);
    const double bound = r0 * r1 * r2;
    if (!(bound > 0) || !(fabs(det) > 1e-12 * bound) || !isfinite(bound)) return -1;
    const double s = 1 / det;
    double r[12];
    r[0] = A * s;
    r[1] = (c * h - b * k) * s;
    r[2] = (b * f - c * e) * s;
    r[4] = B * s;
    r[5] = (a * k - c * g) * s;
    r[6] = (c * d - a * f) * s;
    r[8] = C * s;
    r[9] = (b * g - a * h) * s;
    r[10] = (a * e - b * d) * s;
    /* x = L⁻¹ (y - t), so the translation is -L⁻¹ t. */
    for (int i = 0; i < 3; i++)
        r[4 * i + 3] = -(r[4 * i] * m[3] + r[4 * i + 1] * m[7] + r[4 * i + 2] * m[11]);
    for (int i = 0; i < 12; i++)
        if (!isfinite(r[i])) return -1;
    memcpy(out, r, sizeof r);
    return 0;
}

void csg_affine_point(const csg_affine m, const double p[3], double out[3])
{
    double r[3];
    for (int i = 0; i < 3; i++)
        r[i] = m[4 * i] * p[0] + m[4 * i + 1] * p[1] + m[4 * i + 2] * p[2] + m[4 * i + 3];
    out[0] = r[0];
    out[1] = r[1];
    out[2] = r[2];
}

void csg_affine_vector(const csg_affine m, const double v[3], double out[3])
{
    double r[3];
    for (int i = 0; i < 3; i++)
        r[i] = m[4 * i] * v[0] + m[4 * i + 1] * v[1] + m[4 * i + 2] * v[2];
    out[0] = r[0];
    out[1] = r[1];
    out[2] = r[2];
}

double csg_affine_det(const csg_affine m)
{
    return m[0] * (m[5] * m[10] - m[6] * m[9]) - m[1] * (m[4] * m[10] - m[6] * m[8]) +
           m[2] * (m[4] * m[9] - m[5] * m[8]);
}
