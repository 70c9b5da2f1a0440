/* Ground-truth ambient occlusion (GTAO), Jimenez, Wu, Pesce and Jarabo,
 * "Practical Realtime Strategies for Accurate Indirect Occlusion",
 * SIGGRAPH 2016 course (seeds/001): horizon search on the depth buffer,
 * cosine-weighted IntegrateArc with the normal projected onto each slice,
 * conservative attenuation, thickness heuristic, bent normals and the
 * spatio-temporal sampling pattern. The corrections made to the transcribed
 * slides are listed in gtao.c and README.md.
 *
 * Slice parametrisation (view space, see realtime/screen_space.h): a slice is
 * the plane through the eye that contains the pixel's eye ray and the screen
 * direction (cos phi, sin phi) (pixels, y down), phi in [0, pi). In it, an
 * angle theta is measured from the view vector v = -p / |p| towards the side
 * the screen direction points to (side 2, theta > 0); side 1 has theta < 0.
 * n is the angle of the projected normal, h1 <= 0 <= h2 the two horizons.
 * The average over slices is weighted by d psi / d phi (gtao_slice_weight). */
#ifndef GTLAB_GTAO_GTAO_H
#define GTLAB_GTAO_GTAO_H

#include <stddef.h>
#include <stdint.h>

#include "gtao/gtao_pattern.h"
#include "realtime/screen_space.h"

/* Inner slice integrals, from the view vector out to each horizon:
 * cosine:  sum over h in {h1, h2} of  integral_0^h cos(theta - n) |sin theta| dtheta
 *          = 1/4 (-cos(2 h - n) + cos n + 2 h sin n)  for each side
 * uniform: (1 - cos h1) + (1 - cos h2).
 * An open slice (h = n -+ pi/2) gives 1 per slice on average over phi (cosine,
 * weighted by |n_p|) and 2 (uniform). */
float gtao_integrate_arc_cosine(float h1, float h2, float n);
float gtao_integrate_arc_uniform(float h1, float h2);

/* The cosine-weighted mean direction of a slice's visible arc, unnormalised,
 * as components along v and along the slice's side vector:
 *   (bv, bs) = sum over h in {h1, h2} of integral_0^h (cos theta, sin theta) cos(theta - n) |sin theta| dtheta.
 * Summed over slices (weighted like the visibility) it is the bent normal's
 * direction. The talk's shortcut, the direction halfway between the horizons,
 * is gtao_bent_halfway_angle: on an open plane seen at 45 degrees it is 16
 * degrees off the true bent normal (the normal), so gtlab uses this one. */
void gtao_integrate_arc_bent(float h1, float h2, float n, float *bv, float *bs);
/* The talk's bent direction in a slice: the angle (h1 + h2) / 2. */
static inline float gtao_bent_halfway_angle(float h1, float h2) { return 0.5f * (h1 + h2); }

/* The fast sqrt of Drobot 2014 (integer shift and magic constant) and the
 * first-order acos of Eberly 2014 built on it, as the talk uses them. */
#define GTAO_FAST_SQRT_MAGIC 0x1FBD1DF5u        /* Drobot's constant */
#define GTAO_FAST_SQRT_MAGIC_AS_TRANSCRIBED 0x1FB01DF5u /* the slide's text: 10% low */
float gtao_fast_sqrt_magic(float x, uint32_t magic);
float gtao_fast_sqrt(float x);
float gtao_fast_acos(float x); /* the slide calls it GTAOFastCos */

/* The spatio-temporal pattern of the talk: gtao_pattern.h. */
/* Slice angle phi (radians, [0, pi)) of slice k of `slices` at pixel (x, y)
 * in `frame`, and the step offset in [0, 1) along each side. With the pattern
 * off, slices are regular (phi = pi (k + 0.5) / slices) and the offset 0.5. */
float gtao_slice_angle(int x, int y, int frame, int k, int slices, int pattern);
float gtao_step_offset(int x, int y, int frame, int pattern);

#define GTAO_MAX_STEPS 256
#define GTAO_MAX_SAMPLES 1024 /* per side, in the exact (every cell) mode */

typedef enum { GTAO_COSINE, GTAO_UNIFORM } gtao_weighting;

typedef struct {
    gtao_weighting weighting;
    int slices;          /* slice directions per pixel and frame */
    int steps;           /* depth samples per side of a slice, 1..GTAO_MAX_STEPS; 0: exact, both ends of
                            every pixel cell crossed (up to GTAO_MAX_SAMPLES) */
    float radius;        /* world-space search radius */
    float falloff;       /* fraction of the radius over which samples fade to no effect; 0: full effect to the radius */
    float max_radius_px; /* clamp of the screen-space radius (the talk's cache guard) */
    float thickness;     /* thickness heuristic in [0, 1): how fast a horizon relaxes behind a thin occluder; 0: off */
    int pattern;         /* 1: the talk's spatio-temporal pattern; 0: regular slices, offset 0.5 (brute force);
                            2: the talk's pattern with its directions in Morton order (gtao_pattern.h) */
    int fast_math;       /* the talk's fast acos/sqrt */
    int denoise;         /* the 4x4 bilateral spatial denoiser */
    int frames;          /* frames accumulated by the temporal filter (static camera); 1: a single frame */
    int bent_halfway;    /* bent normal: 0 the exact cosine-weighted arc mean, 1 the talk's halfway direction */
} gtao_params;

/* low, medium (the talk's configuration: 1 direction, 8 samples, denoised),
 * high, ultra, reference (brute force: many slices and samples, no pattern,
 * no denoiser, exact maths). Radius and falloff are left to the caller. */
int gtao_preset(const char *name, gtao_params *p);
extern const char *const gtao_preset_names[]; /* NULL-terminated */
/* The configuration gtlab's GTAO shader ports (gtao.inc), at the
 * defaults of its gtlab.param lines: cosine weighting, 4 regular slices, 8
 * steps per side, radius 1, falloff 0.25, 256 pixels, no thickness, no
 * fast maths, no denoiser, one frame. What the shader is compared with. */
gtao_params gtao_params_shader_port(void);
/* The presets by index into gtao_preset_names. */
typedef enum {
    GTAO_PRESET_LOW,
    GTAO_PRESET_MEDIUM,
    GTAO_PRESET_HIGH,
    GTAO_PRESET_ULTRA,
    GTAO_PRESET_REFERENCE,
    GTAO_PRESET_COUNT
} gtao_preset_id;
/* "weighting=cosine slices=1 ..." for headers and reports. */
void gtao_params_text(const gtao_params *p, char *text, size_t size);

/* The screen points sampled on one side of a slice: `steps` points at
 * distances radius_px (j + offset) / steps, j = 0..steps-1, from the centre
 * of pixel (x, y) along screen direction (dx, dy); points off the image, on
 * background pixels or in the centre pixel are left out. Returns how many
 * were written to xy. Shared by every horizon-based technique so they see
 * the same samples (positions: ss_sample_position). steps = 0: both ends of
 * every pixel cell the line crosses within the radius, which finds the exact
 * horizon of the piecewise-planar height field. */
int ss_side_samples(const ss_gbuffer *g, int x, int y, float dx, float dy, float radius_px, int steps, float offset,
                    float (*xy)[2]);

/* One slice's geometry and horizons, before integration. */
typedef struct {
    vec3 v, side;  /* view vector and the in-slice unit vector towards side 2 (theta = +pi/2) */
    float n;       /* angle of the projected normal */
    float n_len;   /* length of the projected normal */
    float h1, h2;  /* horizon angles clamped to the normal's hemisphere */
    float weight;  /* d psi / d phi: see gtao_slice_weight */
} gtao_slice;

/* Slices are spaced evenly in the screen angle phi, but the integral over
 * slices runs over their rotation psi about the view vector v, and off the
 * image centre psi is not linear in phi. With d = (cos phi, -sin phi, 0) the
 * slice's image-plane direction, d psi / d phi = v.z / (1 - (d . v)^2)
 * (averaging 1 over phi); each slice is weighted by it so the slice average
 * estimates (1/pi) integral over psi exactly. 1 at the image centre. */
float gtao_slice_weight(vec3 v, float phi);

/* The slice's geometry at phi (v, side, n, n_len, weight), without horizons. */
void gtao_slice_geometry(const ss_gbuffer *g, int x, int y, float phi, int fast_math, gtao_slice *s);
/* Searches the horizons of one slice at phi with step offset `offset`. */
void gtao_search_slice(const ss_gbuffer *g, int x, int y, const gtao_params *p, float phi, float offset,
                       gtao_slice *s);

/* The frame of any per-pixel screen-space technique (GTAO, VBAO): fn gives
 * one covered pixel's AO and, when bent is non-NULL, its world-space bent
 * normal; ss_pixel_frame fills ao[i] (and bent[0..2][i] if non-NULL) over
 * the image, background 0; ss_pixel_render runs it through GTAO's frame
 * loop (`frames` frames, each denoised if `denoise`, averaged; gtao_denoiser.h)
 * and normalises the bent normals. Deterministic for any thread count;
 * ss_pixel_render returns 0, or -1 when out of memory. */
typedef void (*ss_pixel_fn)(const ss_gbuffer *g, const void *params, int frame, int x, int y, float *ao, vec3 *bent);
void ss_pixel_frame(const ss_gbuffer *g, ss_pixel_fn fn, const void *params, int frame, float *ao, float *const *bent);
int ss_pixel_render(const ss_gbuffer *g, ss_pixel_fn fn, const void *params, int frames, int denoise, float *ao,
                    float *const *bent);

/* One frame of raw GTAO (no denoiser): ao[i] and, if bent is non-NULL, the
 * world-space bent normal in bent[0..2][i]. Background pixels get 0. */
void gtao_frame(const ss_gbuffer *g, const gtao_params *p, int frame, float *ao, float *const *bent);
/* The whole pipeline: p->frames frames, each denoised if p->denoise, averaged
 * (the temporal accumulation of a static camera). Deterministic for any
 * thread count. Returns 0, or -1 when out of memory. */
int gtao_render(const ss_gbuffer *g, const gtao_params *p, float *ao, float *const *bent);

#endif
