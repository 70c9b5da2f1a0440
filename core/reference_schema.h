/* The format contract of every EXR gtlab writes or reads, in one place
 * (docs/design.md, "EXR channels" and "Header attributes"): the channel
 * names, the suffixes of the Monte Carlo accumulators, and the header
 * attributes with their types. No other file spells a channel or an
 * attribute name: they name these macros, and read or write typed header
 * values through the helpers below.
 *
 * Channels are "layer.channel" (OpenEXR's layer convention, so viewers group
 * them): a scalar quantity is "<layer>.V", a vector one "<layer>.X/Y/Z", a
 * colour "<layer>.R/G/B". Every Monte Carlo quantity Q also has "Q.stderr"
 * (its standard error) and the exact accumulators "Q.sum", "Q.sum_lo",
 * "Q.peak", "Q.m1_0", ... (core/statistics/mc_film.h) from which partial renders merge
 * bit for bit.
 *
 * Header attributes are EXR string attributes (OpenEXR's string type keeps
 * every viewer able to show them); numbers are written as text by the typed
 * helpers ("%.9g" for doubles, which float32 values survive exactly) and read
 * back strictly (the whole string must be a number). */
#ifndef GTLAB_CORE_REFERENCE_SCHEMA_H
#define GTLAB_CORE_REFERENCE_SCHEMA_H

#include "core/error.h"
#include "core/image.h"

/* ---- The G-buffer: the surface seen through each pixel centre ---------- */
#define CH_DEPTH "depth.Z"   /* distance along the primary ray */
#define CH_N_X "N.X"         /* shading normal, world space */
#define CH_N_Y "N.Y"
#define CH_N_Z "N.Z"
#define CH_NG_X "Ng.X"       /* geometric normal */
#define CH_NG_Y "Ng.Y"
#define CH_NG_Z "Ng.Z"
#define CH_P_X "P.X"         /* position, world space */
#define CH_P_Y "P.Y"
#define CH_P_Z "P.Z"
#define CH_ALBEDO_R "albedo.R"
#define CH_ALBEDO_G "albedo.G"
#define CH_ALBEDO_B "albedo.B"
#define CH_ROUGHNESS "roughness.Y" /* perceptual roughness */
#define CH_MASK "mask.A"     /* 1 where the primary ray hit a surface */
/* Initialisers of the vector channels' names, in X, Y, Z order. */
#define CH_N_XYZ {CH_N_X, CH_N_Y, CH_N_Z}
#define CH_NG_XYZ {CH_NG_X, CH_NG_Y, CH_NG_Z}
#define CH_P_XYZ {CH_P_X, CH_P_Y, CH_P_Z}
#define CH_ALBEDO_RGB {CH_ALBEDO_R, CH_ALBEDO_G, CH_ALBEDO_B}

/* ---- Monte Carlo bookkeeping (core/statistics/mc_film.h) --------------------------- */
#define CH_SPP "spp.N"           /* samples taken in the pixel */
#define CH_SPP_EVEN "spp.Neven"  /* of which even-indexed (the noise-floor halves) */
#define CH_SPP_LO "spp.Nlo"      /* count - spp.N exactly: spp.N is the count rounded to */
#define CH_SPP_EVEN_LO "spp.Nevenlo" /* a float, for people; hi + lo is exact to 2^32 */
#define CH_LAYER_SPP "spp"       /* their layer */
#define CH_SUFFIX_STDERR "stderr" /* "Q.stderr": standard error of Q's mean */
#define CH_SUFFIX_SUM "sum"      /* exact accumulators on the quantity's grid: see core/statistics/mc_film.h */
#define CH_SUFFIX_SUM_LO "sum_lo"
#define CH_SUFFIX_SUMEVEN "sumeven"
#define CH_SUFFIX_SUMEVEN_LO "sumeven_lo"
/* Moment sums at the pixel's scale (core/statistics/moment_sums.h), what Q.stderr comes
 * from: the largest |sample|, and limb k of the sum of samples (moment 1) or
 * of their squares (moment 2) as hi + lo floats, "Q.m1_0", "Q.m1_0lo", ... */
#define CH_SUFFIX_PEAK "peak"
#define CH_SUFFIX_LIMB_FMT "m%d_%d%s" /* moment (1, 2), limb (0 .. 2), "" or CH_SUFFIX_LIMB_LO */
#define CH_SUFFIX_LIMB_LO "lo"
/* A third float, "<lo channel>2" ("Q.sum_lo2", "Q.m1_0lo2"), written only
 * when some pixel's sum needs more than hi + lo's 48 bits (more than 2^24
 * samples): hi + lo + lo2 is exact to 2^72. Absent, it is 0. */
#define CH_SUFFIX_THIRD_PART "2"
/* Files written before issue 23 summed squares on the grid instead: read for
 * their means, refused for merges (their standard errors were wrong). */
#define CH_SUFFIX_SUMSQ_LEGACY "sumsq"

/* ---- Ambient occlusion (render ao, heightfield-ao, approx gtao/hbao/vo) -- */
#define CH_AO "ao.V"               /* cosine-weighted visibility V_d */
#define CH_AO_UNIFORM "ao.Vuniform" /* uniformly weighted visibility */
#define CH_AO_STDERR "ao.V.stderr"
#define CH_BENT_X "bent.X"         /* bent normal (unit, world space) */
#define CH_BENT_Y "bent.Y"
#define CH_BENT_Z "bent.Z"
#define CH_BENT_XYZ {CH_BENT_X, CH_BENT_Y, CH_BENT_Z}
#define CH_LAYER_BENT "bent"

/* ---- Multi-bounce diffuse (render multibounce) -------------------------- */
#define CH_MULTIBOUNCE "multibounce.V" /* one albedo */
#define CH_MULTIBOUNCE_R "multibounce.R" /* the scene's albedo, per colour */
#define CH_MULTIBOUNCE_G "multibounce.G"
#define CH_MULTIBOUNCE_B "multibounce.B"
#define CH_MULTIBOUNCE_RGB {CH_MULTIBOUNCE_R, CH_MULTIBOUNCE_G, CH_MULTIBOUNCE_B}
/* Several albedos: "multibounce_<albedo>.V", albedo as multibounce_albedos_text prints it. */
#define CH_MULTIBOUNCE_ALBEDO_FMT "multibounce_%s.V"

/* ---- Specular occlusion (render specular-occlusion, approx) ------------- */
#define CH_SPECOCC "specocc.V"             /* GTSO's definition: f_r-weighted */
#define CH_SPECOCC_D "specocc_d.V"         /* D-weighted (the talk's older one) */
#define CH_SPECOCC_PHONG "specocc_phong.V" /* Phong-lobe weighted */
/* Each definition's ratio is derived from three sums, "<prefix>_<part>.V". */
#define CH_SPECOCC_PREFIX "specocc"
#define CH_SPECOCC_D_PREFIX "specocc_d"
#define CH_SPECOCC_PHONG_PREFIX "specocc_phong"
#define CH_SPECOCC_PART_FMT "%s_%s.V"      /* prefix, part */
#define CH_SPECOCC_PART_OCCLUDED "occluded"
#define CH_SPECOCC_PART_UNOCCLUDED "unoccluded"
#define CH_SPECOCC_PART_BLOCKED "blocked"
#define CH_SPECOCC_OCCLUDED "specocc_occluded.V"
#define CH_SPECOCC_UNOCCLUDED "specocc_unoccluded.V"
#define CH_SPECOCC_BLOCKED "specocc_blocked.V"
#define CH_SPECOCC_D_OCCLUDED "specocc_d_occluded.V"
#define CH_SPECOCC_D_UNOCCLUDED "specocc_d_unoccluded.V"
#define CH_SPECOCC_D_BLOCKED "specocc_d_blocked.V"
#define CH_SPECOCC_PHONG_OCCLUDED "specocc_phong_occluded.V"
#define CH_SPECOCC_PHONG_UNOCCLUDED "specocc_phong_unoccluded.V"
#define CH_SPECOCC_PHONG_BLOCKED "specocc_phong_blocked.V"
/* The GTSO talk's split integrals under the analytic sky (--environment sky). */
#define CH_SPLIT_TRUTH "split_truth.V"
#define CH_SPLIT_TWO "split_two.V"
#define CH_SPLIT_THREE "split_three.V"
#define CH_SPLIT_ENV_D_OCCLUDED "split_env_d_occluded.V"
#define CH_SPLIT_ENV_D_UNOCCLUDED "split_env_d_unoccluded.V"

/* ---- GGX sphere lights (render sphere-light) ---------------------------- */
#define CH_SPHERE_R "sphere.R"
#define CH_SPHERE_G "sphere.G"
#define CH_SPHERE_B "sphere.B"
#define CH_SPHERE_RGB {CH_SPHERE_R, CH_SPHERE_G, CH_SPHERE_B}

/* ---- Height fog (render fog; techniques/height_fog/height_fog_integrator.h) --- */
/* Transmittance of the fog from the camera to the surface (closed form). */
#define CH_FOG_T_R "fog.T.R"
#define CH_FOG_T_G "fog.T.G"
#define CH_FOG_T_B "fog.T.B"
#define CH_FOG_T_RGB {CH_FOG_T_R, CH_FOG_T_G, CH_FOG_T_B}
/* Radiance the fog scatters towards the camera (sun + ambient). */
#define CH_FOG_L_R "fog.L.R"
#define CH_FOG_L_G "fog.L.G"
#define CH_FOG_L_B "fog.L.B"
#define CH_FOG_L_RGB {CH_FOG_L_R, CH_FOG_L_G, CH_FOG_L_B}
/* --fog-scattering quadrature: the quadrature's error estimate of fog.L. */
#define CH_FOG_L_ERROR_R "fog_quadrature_error.R"
#define CH_FOG_L_ERROR_G "fog_quadrature_error.G"
#define CH_FOG_L_ERROR_B "fog_quadrature_error.B"
#define CH_FOG_L_ERROR_RGB {CH_FOG_L_ERROR_R, CH_FOG_L_ERROR_G, CH_FOG_L_ERROR_B}

/* The fog study's error maps (height_fog/height_fog_study.c, fog/<weather>_sunNN.exr):
 * the analytic model's fog.L minus the reference's, green channel. */
#define CH_FOG_PUBLISHED_ERROR "fog_published_error.G"
#define CH_FOG_CORRECTED_ERROR "fog_corrected_error.G"

/* The combination images of the Decima fog (height_fog/aerial_perspective_study.h,
 * fog/aerial_<weather>_sunNN.exr and fog/fisheye_<weather>_sunNN.exr): the
 * atmosphere's radiance towards the camera by quadrature (reference), the
 * LUTs + published HeightFog() (model) and + the corrected one (sun and sky
 * attenuated); mask.A marks the terrain (aerial) or the fisheye's circle. */
#define CH_AERIAL_REFERENCE_RGB {"aerial_reference.R", "aerial_reference.G", "aerial_reference.B"}
#define CH_AERIAL_MODEL_RGB {"aerial_model.R", "aerial_model.G", "aerial_model.B"}
#define CH_AERIAL_CORRECTED_RGB {"aerial_model_corrected.R", "aerial_model_corrected.G", "aerial_model_corrected.B"}

/* ---- Volumetric light (render volumetric-light;
 * techniques/volumetric_light/volumetric_light_integrator.h) ------------ */
/* Radiance a spot or point light scatters once towards the camera through a
 * homogeneous medium, shadowed, up to the first surface. */
#define CH_VLIGHT_L_R "vlight.L.R"
#define CH_VLIGHT_L_G "vlight.L.G"
#define CH_VLIGHT_L_B "vlight.L.B"
#define CH_VLIGHT_L_RGB {CH_VLIGHT_L_R, CH_VLIGHT_L_G, CH_VLIGHT_L_B}
/* --vlight-method quadrature: the quadrature's error estimate of vlight.L. */
#define CH_VLIGHT_L_ERROR_R "vlight_quadrature_error.R"
#define CH_VLIGHT_L_ERROR_G "vlight_quadrature_error.G"
#define CH_VLIGHT_L_ERROR_B "vlight_quadrature_error.B"
#define CH_VLIGHT_L_ERROR_RGB {CH_VLIGHT_L_ERROR_R, CH_VLIGHT_L_ERROR_G, CH_VLIGHT_L_ERROR_B}
/* ---- Environment lighting (render env-diffuse, env-specular;
 *      techniques/environment/environment_{diffuse,specular}_integrator.h) */
/* Lambertian L / albedo with visibility and --bounces inter-reflections. */
#define CH_ENV_DIFFUSE_RGB {"env_diffuse.R", "env_diffuse.G", "env_diffuse.B"}
/* The same, direct light only (no inter-reflection). */
#define CH_ENV_DIFFUSE_DIRECT_RGB {"env_diffuse_direct.R", "env_diffuse_direct.G", "env_diffuse_direct.B"}
/* The same directions with visibility off: (1/pi) \int L max(0, n.w) dw. */
#define CH_ENV_DIFFUSE_UNOCCLUDED_RGB \
    {"env_diffuse_unoccluded.R", "env_diffuse_unoccluded.G", "env_diffuse_unoccluded.B"}
/* GGX specular radiance with visibility, and without, from the same samples. */
#define CH_ENV_SPECULAR_RGB {"env_specular.R", "env_specular.G", "env_specular.B"}
#define CH_ENV_SPECULAR_UNOCCLUDED_RGB \
    {"env_specular_unoccluded.R", "env_specular_unoccluded.G", "env_specular_unoccluded.B"}

/* ---- Lookup tables (gtlab lut) ------------------------------------------ */
#define CH_LUT "lut.V"
/* The split-sum DFG table (luts/dfg_lut.h): scale A, bias B, albedo E = A + B. */
#define CH_DFG_A "dfg.A"
#define CH_DFG_B "dfg.B"
#define CH_DFG_E "dfg.E"
/* The GGX LTC table (techniques/ltc/ltc_ggx.h): M^-1's a, b, c, d, the magnitude E,
 * the Fresnel term B, and the fit's total-variation error per texel. */
#define CH_LTC_NAMES {"ltc.a", "ltc.b", "ltc.c", "ltc.d", "ltc.E", "ltc.B"}
#define CH_LTC_ERROR "ltc.error"
/* The best-fit normals table (best_fit_normals/best_fit_normals.h): the scale t per texel. */
#define CH_BEST_FIT_SCALE "best_fit.t"
/* Blue-noise dither textures (luts/blue_noise.h): one channel per seed. */
#define CH_BLUE_NOISE_R "blue_noise.R"
#define CH_BLUE_NOISE_G "blue_noise.G"
#define CH_BLUE_NOISE_B "blue_noise.B"
#define CH_BLUE_NOISE_A "blue_noise.A"
#define CH_BLUE_NOISE_RGBA {CH_BLUE_NOISE_R, CH_BLUE_NOISE_G, CH_BLUE_NOISE_B, CH_BLUE_NOISE_A}
/* The Decima atmosphere LUTs (atmosphere/atmosphere_luts.h): in-scatter per species
 * without phase, the sun and the sky light reaching an altitude. */
#define CH_ATMOSPHERE_INSCATTER_RAYLEIGH {"inscatter.rayleigh.R", "inscatter.rayleigh.G", "inscatter.rayleigh.B"}
#define CH_ATMOSPHERE_INSCATTER_MIE {"inscatter.mie.R", "inscatter.mie.G", "inscatter.mie.B"}
#define CH_ATMOSPHERE_SUN {"sun.R", "sun.G", "sun.B"}
#define CH_ATMOSPHERE_SKY {"sky.R", "sky.G", "sky.B"}

/* Frames for temporal anti-aliasing (`gtlab render frames`, techniques/anti_aliasing/frames_render.h). */
#define CH_FRAME_RGB {"frame.R", "frame.G", "frame.B"} /* linear radiance of the jittered sample */
#define CH_MOTION_X "motion.X"           /* previous image position minus this one, pixels */
#define CH_MOTION_Y "motion.Y"
#define CH_DISOCCLUDED "disoccluded.V"   /* 1 where the previous frame did not see the point */
#define CH_FRAME_TRUTH_RGB {"truth.R", "truth.G", "truth.B"} /* the supersampled, filtered truth of the frame */

/* ---- Header attributes -------------------------------------------------- */
/* text */
#define ATTR_JITTER "gtlab.jitter"       /* a frame's sub-pixel jitter "x y" (frames) */
#define ATTR_FRAME "gtlab.frame"         /* a frame's index on its camera path */
#define ATTR_TRUTH "gtlab.truth"         /* how a frame's truth was made: "S x S strata, FILTER, seed N" */
#define ATTR_VERSION "gtlab.version"     /* the gtlab version that wrote the file */
#define ATTR_QUANTITY "gtlab.quantity"   /* "ao", "gbuffer", ..., "approx" */
#define ATTR_SCENE "gtlab.scene"         /* the scene spec ("builtin:boxes", a path) */
#define ATTR_SCENE_HASH "gtlab.scene_hash" /* SHA-256 of the loaded scene (scene/scene_hash.h) */
#define ATTR_CAMERA "gtlab.camera"       /* the camera as JSON (scene/camera.h) */
#define ATTR_NORMAL "gtlab.normal"       /* "shading" or "geometric" */
#define ATTR_SETTINGS "gtlab.settings"   /* the integrator's options, for people to read */
#define ATTR_BLOCKS "gtlab.sample_blocks" /* "seed:offset+count ..." */
#define ATTR_CHECKPOINT_OF "gtlab.checkpoint_of" /* a checkpoint: the header of the render it belongs to */
#define ATTR_CHECKPOINT_ROWS "gtlab.checkpoint_rows" /* an adaptive render's checkpoint: the rows finished */
#define ATTR_CHECKPOINT_RANK "gtlab.checkpoint_rank" /* an MPI rank's checkpoint: "r/N", its rank of N */
#define ATTR_ALBEDOS "gtlab.albedos"     /* multibounce: the albedo list */
#define ATTR_BOUNCES "gtlab.bounces"     /* multibounce: bounce count or "inf" */
#define ATTR_NORMALIZED "gtlab.normalized" /* "layer layer ...": vector layers written normalised */
#define ATTR_EXPONENTS "gtlab.scale_exponents" /* "name:E ...": the film's exact-sum scales */
#define ATTR_TECHNIQUE "gtlab.technique" /* approx output: the technique */
#define ATTR_APPROX "gtlab.approx"       /* approx specular-occlusion: the variant's label */
#define ATTR_LUT "gtlab.lut"             /* a LUT's axes and parametrisation */
#define ATTR_LUT_SIZES "gtlab.lut.sizes" /* a multi-axis LUT's sizes, "N0 N1 N2 N3" (its image: N0*N1 x N2*N3) */
#define ATTR_LUT_PARAMETRIZATION "gtlab.lut.parametrization" /* its axes' mappings: "linear", "yusov2013", ... */
#define ATTR_CONTROL_VARIATE "gtlab.control_variate" /* ao: "none" or "heightfield"; absent: none */
#define ATTR_ENVIRONMENT "gtlab.environment" /* env-*: "white", "sky", "sun" or the file */
/* integer */
#define ATTR_SPP "gtlab.spp"
#define ATTR_SEED "gtlab.seed"
/* real */
#define ATTR_LUT_ERROR "gtlab.lut.error" /* a LUT's largest quadrature error estimate */
#define ATTR_ENV_ROTATE "gtlab.env_rotate"   /* env-*: degrees about +Y */
#define ATTR_ENV_INTENSITY "gtlab.env_intensity" /* env-*: radiance factor */
#define ATTR_F0 "gtlab.f0"                   /* env-specular: the fixed F0, absent: the materials' */
#define ATTR_ROUGHNESS "gtlab.roughness" /* specular occlusion: the fixed roughness, absent: the materials' */
#define ATTR_TARGET_STDERR "gtlab.target_stderr"         /* --target-stderr; absent: none */
#define ATTR_TARGET_REL_STDERR "gtlab.target_rel_stderr" /* --target-rel-stderr; absent: none */

/* Values of ATTR_QUANTITY written by other than a reference integrator. */
#define QUANTITY_NAME_APPROX "approx"

/* "<quantity>.<suffix>" into name (IMAGE_NAME_MAX); 0, or -1 if too long. */
int schema_channel_suffixed(const char *quantity, const char *suffix, char name[IMAGE_NAME_MAX]);
/* The standard-error channel of a quantity channel, or NULL when absent. */
const float *schema_stderr_data(const image *img, const char *quantity);

/* Typed header values. Setters return 0, or -1 when out of memory. */
int schema_set_int(image *img, const char *key, long value);
int schema_set_real(image *img, const char *key, double value);
/* Getters return 1 and the value when the attribute is present and valid,
 * 0 when absent, -1 (with e naming `what`) when present but not a number. */
int schema_get_int(const image *img, const char *key, const char *what, long *value, gt_error *e);
int schema_get_real(const image *img, const char *key, const char *what, double *value, gt_error *e);

#endif
