/*
 * shade.c — the lighting of OpenSCAD's preview, which is OpenGL's fixed
 * pipeline as GLView::initializeGL sets it up (OpenSCAD 2021.01,
 * src/GLView.cc):
 *   - two directional lights, diffuse (1,1,1), positions (-1,-1,+1,0) and
 *     (+1,+1,-1,0), given while the modelview matrix is the identity;
 *   - glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE): the object
 *     colour is both ambient and diffuse material; the lights' own ambient
 *     is GL's default 0 and the light model ambient GL's default 0.2;
 *   - no specular (material specular stays GL's default 0), no two-sided
 *     model: back faces are lit with the front normal.
 * GLView::setupCamera issues gluLookAt((0,-dist,0), 0, +z) while the matrix
 * mode is still GL_PROJECTION, so the modelview holds only the gimbal
 * rotation (and translation).  Lighting therefore happens in that rotated
 * world: x = right, y = forward (into the screen), z = up — not in GL's
 * usual eye space.  The light (-1,-1,1) comes from the left, from the viewer
 * and from above.  Measured against OpenSCAD's PNG of cube([10,20,5]) in the
 * default view: top 250/249 of #f9d72c (0.2 + 0.804, clamped), the two sides
 * 0.663 and 0.574 — which this model reproduces and GL eye space does not.
 * So colour = base · (0.2 + max(0, n'·L0) + max(0, n'·L1)) with L0 = -L1 =
 * (-1,-1,1)/√3, i.e. base · (0.2 + |n'·L0|), clamped per channel.  A face
 * squarely toward the viewer (n' = (0,-1,0)) gets 0.2 + 1/√3 ≈ 0.777.
 * Because the lights are opposite, the sign of n does not matter: flipped
 * (subtracted) and exiting surfaces shade like the faces OpenSCAD draws.
 */
#include "shade.h"

#include <math.h>

double render_shade_factor(const render_camera *c, const double n[3])
{
    /* The normal in the gimbal-rotated world: (right, forward, up). */
    double nx = n[0] * c->right[0] + n[1] * c->right[1] + n[2] * c->right[2];
    double ny = n[0] * c->forward[0] + n[1] * c->forward[1] + n[2] * c->forward[2];
    double nz = n[0] * c->up[0] + n[1] * c->up[1] + n[2] * c->up[2];
    const double k = 0.57735026918962576; /* 1/√3: L0 = k·(-1,-1,1) */
    double d0 = k * (-nx - ny + nz), d1 = -d0;
    return 0.2 + (d0 > 0 ? d0 : 0) + (d1 > 0 ? d1 : 0);
}

void render_shade_apply(const float rgb[3], double factor, float out[3])
{
    for (int i = 0; i < 3; i++) {
        double v = rgb[i] * factor;
        out[i] = (float)(v < 0 ? 0 : v > 1 ? 1 : v);
    }
}
