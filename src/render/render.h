/*
 * render.h — cameras that follow OpenSCAD's conventions, and the image
 * renderer: primary rays through a csg_scene, visibility first, shading once
 * at the visible boundaries, colour alpha composited front to back.
 */
#ifndef RAYSCAD_RENDER_H
#define RAYSCAD_RENDER_H

#include "../csg/csg.h"

/* A resolved pinhole or orthographic camera in world space. */
typedef struct render_camera {
    double eye[3];            /* position (perspective) / reference point (ortho) */
    double forward[3];        /* unit view direction */
    double up[3];             /* unit, orthogonal to forward */
    double right[3];          /* unit, forward × up */
    double fovy_deg;          /* vertical field of view, perspective */
    double ortho_half_height; /* half the visible height, orthographic */
    int ortho;                /* 1: orthographic projection */
    /* The depth range OpenSCAD's projection keeps, measured along forward
     * from eye: perspective [0.1·dist, 100·dist], orthographic
     * [-100·dist, 100·dist] (GLView::setupCamera).  Both 0: no clipping. */
    double clip_near, clip_far;
} render_camera;

/* The view as OpenSCAD's command line states it. */
typedef enum render_camera_kind {
    RENDER_CAMERA_DEFAULT, /* no --camera: rotation 55,0,25, viewall+autocenter */
    RENDER_CAMERA_GIMBAL,  /* --camera=tx,ty,tz,rx,ry,rz,dist */
    RENDER_CAMERA_EYE      /* --camera=ex,ey,ez,cx,cy,cz */
} render_camera_kind;

typedef struct render_view {
    render_camera_kind kind;
    double v[7];    /* the --camera numbers */
    int viewall;    /* --viewall */
    int autocenter; /* --autocenter */
    int ortho;      /* --projection=o */
    /* With no --camera (kind DEFAULT), the file's own $vpr/$vpt/$vpd/$vpf
     * as scad_result holds them: file_vp_set says which are usable (bits
     * 1, 2, 4, 8 in that order), file_vp_auto_off turns viewall and
     * autocenter off, as OpenSCAD 2021.01's Camera::updateView does. */
    int file_vp_set, file_vp_auto_off;
    double vpr[3], vpt[3], vpd, vpf;
} render_view;

/* Resolve a view for an image of width × height pixels and a model whose
 * bounds are lo/hi (used by viewall/autocenter; pass have_bounds = 0 for an
 * empty model).  Follows OpenSCAD 2021.01 exactly (22.5° vertical field of
 * view, its viewall distance and centring), so that the images line up
 * pixel for pixel.  Returns 0, or -1 for a degenerate view (eye == centre). */
int render_camera_resolve(const render_view *v, const double lo[3], const double hi[3],
                          int have_bounds, int width, int height, render_camera *out);

/* The world ray through image position (px, py) in pixels, (0,0) the
 * top-left corner of the top-left pixel: origin o and direction d (unit). */
void render_camera_ray(const render_camera *c, int width, int height, double px, double py,
                       double o[3], double d[3]);

/* The same rays precomputed for one image size, for the per-pixel loops:
 * o = org + px·odx + py·ody and d = d0 + px·ddx + py·ddy, normalised. */
typedef struct render_raygen {
    double org[3], odx[3], ody[3];
    double d0[3], ddx[3], ddy[3];
} render_raygen;

void render_raygen_init(render_raygen *g, const render_camera *c, int width, int height);
void render_raygen_ray(const render_raygen *g, double px, double py, double o[3], double d[3]);

/* The image rectangle rect = {x0, x1, y0, y1} (pixel coordinates, as
 * render_raygen_ray takes them) outside which every ray of g misses the box
 * [lo, hi]: the bounds of its corners' projections, widened by a pixel.
 * Returns 0, or -1 when there is no such rectangle to state (an infinite
 * box, or one reaching to or behind the eye). */
int render_raygen_cover(const render_raygen *g, const double lo[3], const double hi[3],
                        double rect[4]);

/* An OpenSCAD colour scheme, sRGB in [0, 1]. */
typedef struct render_colors {
    float background[3];
    float face[3];                /* objects with no color() */
    float back[3];                /* subtracted surfaces with no color() */
    float highlight[4];           /* '#' subtrees: OpenSCAD's transparent pink */
    float background_modifier[4]; /* '%' subtrees: transparent grey */
} render_colors;

/* Fill *out with scheme `name` ("Cornfield", "Metallic", …, as OpenSCAD
 * names them).  Returns 0, or -1 for an unknown name. */
int render_colors_by_name(const char *name, render_colors *out);

/* A point light, or with radius > 0 a spherical area light whose shadow
 * rays are spread, stratified, over the disc it shows each shaded point. */
typedef struct render_light {
    double pos[3];    /* world position */
    double radius;    /* >= 0, world units */
    double intensity; /* > 0; 1 gives a face squarely toward it 0.2 + 1 */
} render_light;

enum { RENDER_MAX_LIGHTS = 16 };

typedef struct render_options {
    int width, height;
    int samples; /* samples per pixel is samples², stratified; >= 1 */
    int threads; /* worker threads; <= 0: all cores */
    /* Spans one interval list may hold while a ray is traced (the workers'
     * iv_arena_set_list_limit); <= 0: IV_LIST_LIMIT_DEFAULT. */
    int max_intervals;
    render_colors colors;
    /* Called from the calling thread with the fraction done; may be NULL. */
    void (*progress)(void *ud, double done);
    void *ud;

    /* ---- opt-in light model ---------------------------------------------
     * Every field below left 0 (and no $rs_ material in the scene) gives
     * OpenSCAD's preview look, byte for byte as before they existed. */
    int shadows;                            /* 1: shadow rays.  With no lights, the key light is the
                                               preview's own (from the viewer's upper left, at
                                               infinity) and its opposite fill stays unshadowed. */
    render_light lights[RENDER_MAX_LIGHTS]; /* replace the preview's lights */
    int nlights;
    int light_samples; /* area lights: n×n shadow rays per light; 0: 4 */
    int bounces;       /* depth limit of mirror and refraction rays; 0: 4 */
    double ior;        /* > 1: transparent solids without $rs_ior refract
                          with this index (--refract) */
    double aperture;   /* thin-lens diameter, world units; 0: pinhole */
    double focus;      /* focal distance from the eye; 0: to the centre of
                          the model's bounds */
    double xray;       /* in (0, 1]: every surface at most this opaque */
    double absorb;     /* > 0: absorption mode; a transparent solid's alpha
                          is the opacity of this thickness (world units),
                          Beer–Lambert over the length of its spans */
    unsigned seed;     /* the jitter's seed; pixels derive their own */
    int path_trace;    /* > 0: path-trace the model root with this many
                          samples per pixel (src/render/path_trace.c:
                          diffuse interreflection, next-event estimation,
                          Fresnel glass); `samples` is then unused */
} render_options;

/* Scene roots by role: root 0 is the model; root 1, when present, the '#'
 * highlight subtrees (drawn in colors.highlight over the model); root 2, when
 * present, the '%' background subtrees (drawn in colors.background_modifier).
 * An empty root is simply absent from the image. */
enum { RENDER_ROOT_MODEL = 0, RENDER_ROOT_HIGHLIGHT = 1, RENDER_ROOT_BACKGROUND = 2 };

/* Render the roots of scene s, composited front to back, into
 * rgba: width*height*4 floats, row-major from the top row, sRGB-encoded,
 * alpha 1 where the background shows.  The result is identical for any
 * thread count (random numbers, when the light model draws any, come from
 * per-pixel streams).  The light model is on when opt asks for shadows,
 * lights or a lens, or when the scene has emitters ($rs_light); materials
 * with reflect, absorb or ior take effect in either look.  Returns 0, or
 * with a message in err: -1 (out of memory, bad options) or
 * RENDER_ERR_INTERVALS.  Nothing is promised about rgba after a failure. */
enum {
    RENDER_ERR_INTERVALS = -2 /* a ray's interval list passed opt->max_intervals */
};
int render_image(const csg_scene *s, const render_camera *cam, const render_options *opt,
                 float *rgba, char *err, size_t errlen);


/* The roots of scene s as POV-Ray 3.7 SDL (src/render/pov_export.c): the
 * same solids as analytic POV primitives and CSG, colours as srgbt
 * pigments, camera cam as an image of opt->width × opt->height, the
 * preview's lights and opt->colors' background.  On success *text is a
 * malloc'd string of *len bytes (NUL-terminated), owned by the caller.
 * Returns 0, or -1 with a message in err (out of memory, CSG too deep). */
int render_pov_export(const csg_scene *s, const render_camera *cam, const render_options *opt,
                      char **text, size_t *len, char *err, size_t errlen);

#endif
