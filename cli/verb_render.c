/* gtlab render QUANTITY: a reference image rendered with Embree. */
#define _GNU_SOURCE
#include <getopt.h>
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <string.h>

#include "cli/cli.h"
#include "core/atomic_file.h"
#include "core/exr_io.h"
#include "raytracer/reference_render.h"
#include "scene/scene_loaders.h"

static void print_help(void)
{
    printf(
        "usage: gtlab render QUANTITY --scene F.glb|builtin:NAME -o out.exr [options]\n"
        "\n"
        "Renders a reference quantity at the surface seen through each pixel centre.\n"
        "QUANTITY:\n"
        "  gbuffer   depth.Z, N.*, Ng.*, P.*, albedo.*, roughness.Y, mask.A\n"
        "  ao        the G-buffer plus ao.V (cosine AO), ao.Vuniform (uniform AO),\n"
        "            bent.X/Y/Z (bent normal), each with .stderr and the exact\n"
        "            accumulators (.sum, .sumsq, .sumeven) that 'gtlab merge' combines\n"
        "  multibounce  the G-buffer plus V'_d = L / albedo: the radiance of Lambertian\n"
        "            surfaces of that albedo under a uniform white dome of radiance 1,\n"
        "            divided by the albedo (GTAO's multi-bounce AO), and ao.V (V_d) of the\n"
        "            same pixels. Channels: multibounce.V (one albedo), multibounce_<a>.V\n"
        "            for each of several (e.g. multibounce_0.3.V), or multibounce.R/G/B with\n"
        "            --albedo scene; the header holds gtlab.albedos and gtlab.bounces\n"
        "  heightfield-ao  the G-buffer plus ao.V and ao.Vuniform where rays are blocked\n"
        "            only by the depth buffer taken as a height field (infinite thickness,\n"
        "            rays leaving the image escape): what screen-space AO can know\n"
        "  sphere-light  the G-buffer plus sphere.R/G/B: radiance towards the camera from a\n"
        "            uniform spherical light over the glTF materials (Lambert + GGX with\n"
        "            Schlick Fresnel), integrated exactly over the light (MIS); unshadowed\n"
        "            like the real-time approximations unless --shadows\n"
        "  specular-occlusion  the G-buffer plus GTSO specular occlusion under a white\n"
        "            dome: specocc.V = integral of V f_r cos / integral of f_r cos (GGX,\n"
        "            no Fresnel, view from the camera), specocc_d.V (the older D-only\n"
        "            definition), specocc_phong.V (the same with Phong's NDF,\n"
        "            p = 2/alpha^2 - 2), and the integrals: specocc_occluded.V,\n"
        "            specocc_unoccluded.V (directional albedo), specocc_d_*.V,\n"
        "            specocc_phong_*.V; ratios'\n"
        "            standard errors by the delta method. With --environment sky also\n"
        "            the GTSO talk's split integrals under an analytic sky: split_truth.V\n"
        "            (integral of V L f_r cos), split_two.V, split_three.V\n"
        "\n"
        "options:\n"
        "  --scene S             a .gltf/.glb file or builtin:NAME ('gtlab scene list')\n"
        "  --camera cam.json     camera JSON (default: the scene's camera, else a 3/4 view)\n"
        "  --width W --height H  image size (one alone keeps the camera's aspect ratio)\n"
        "  --spp N               samples per pixel, at most (default 64)\n"
        "  --seed S              sequence seed (default 1)\n"
        "  --sample-offset K     first sample index: renders the block [K, K+N) so blocks\n"
        "                        of one seed can be rendered apart and merged\n"
        "  --target-stderr E     stop a pixel once the standard error of its first channel\n"
        "                        (ao.V; multibounce: the first multibounce channel;\n                        specular-occlusion: specocc_occluded.V) is <= E\n"
        "                        (checked at 16, 32, 64, ... samples)\n"
        "  --max-distance D      ao, heightfield-ao: rays farther than D count as\n"
        "                        unoccluded (default: none)\n"
        "  --albedo A,B,...|scene  multibounce (required): grey albedos in [0, 1], all\n"
        "                        rendered from the same paths in one pass, or 'scene': the\n"
        "                        glTF base colours (textures included), coloured R, G, B\n"
        "  --bounces N|inf       multibounce: inter-reflections after the first hit\n"
        "                        (0 gives V_d; default 4, as the GTAO talk); 'inf' ends paths\n"
        "                        by Russian roulette instead (unbiased)\n"
        "  --light-position X,Y,Z  sphere-light (required): the light's centre\n"
        "  --light-radius R      sphere-light (required): its radius, > 0\n"
        "  --light-radiance L    sphere-light: its emitted radiance (default 1)\n"
        "  --shadows             sphere-light: the scene's geometry blocks the light (one\n"
        "                        occlusion ray per light-carrying sample direction)\n"
        "  --environment E       specular-occlusion: white (default) or sky, which adds the\n"
        "                        two- vs three-split channels (docs/decisions.md, the sky)\n"
        "  --roughness R         specular-occlusion: perceptual roughness in [0, 1] for\n"
        "                        every surface (GGX alpha = R^2); default: the glTF material\n"
        "  --normal shading|geometric   normal the hemisphere is built on (default shading)\n"
        "  --threads T           worker threads (default: all cores); the output does not\n"
        "                        depend on it\n"
        "  -o, --output F.exr    output EXR; the camera used goes to F.camera.json\n"
        "  -h, --help\n");
}

typedef struct {
    const char *scene, *camera, *output;
    long width, height;
    reference_request request;
    const char *albedo, *bounces, *max_distance, *roughness, *environment; /* as given, or NULL */
    const char *light_position, *light_radius, *light_radiance; /* as given, or NULL */
    int shadows;
} render_options;

/* "X,Y,Z": three finite numbers. */
static int parse_position(const char *option, const char *text, vec3 *out)
{
    double v[3];
    char extra;
    if (sscanf(text, "%lf,%lf,%lf%c", &v[0], &v[1], &v[2], &extra) != 3 || !isfinite(v[0]) || !isfinite(v[1]) ||
        !isfinite(v[2]))
        return cli_failf(option, "'%s' is not three numbers X,Y,Z", text), -1;
    *out = v3((float)v[0], (float)v[1], (float)v[2]);
    return 0;
}

/* The sphere-light options: refused with other quantities, required with it. */
static int check_light_options(render_options *o)
{
    const char *given = o->light_position ? "--light-position" : o->light_radius ? "--light-radius"
                        : o->light_radiance                   ? "--light-radiance"
                        : o->shadows                          ? "--shadows" : NULL;
    if (o->request.quantity != QUANTITY_SPHERE_LIGHT)
        return given ? (cli_failf(given, "applies to sphere-light only"), -1) : 0;
    if (!o->light_position || !o->light_radius)
        return cli_failf("render", "sphere-light needs --light-position and --light-radius"), -1;
    double radius, radiance = 1.0;
    sphere_light_settings *l = &o->request.sphere_light;
    if (parse_position("--light-position", o->light_position, &l->position) != 0 ||
        cli_parse_double("--light-radius", o->light_radius, 1e-30, 1e30, &radius) != 0 ||
        (o->light_radiance && cli_parse_double("--light-radiance", o->light_radiance, 1e-30, 1e30, &radiance) != 0))
        return -1;
    l->radius = (float)radius, l->radiance = (float)radiance, l->shadows = o->shadows;
    return 0;
}

/* The options that belong to one quantity only are refused with the others. */
static int check_quantity_options(render_options *o)
{
    gt_error e;
    int multibounce = o->request.quantity == QUANTITY_MULTIBOUNCE;
    if (o->max_distance && o->request.quantity != QUANTITY_AO && o->request.quantity != QUANTITY_HEIGHTFIELD_AO)
        return cli_failf("--max-distance", "applies to ao and heightfield-ao only"), -1;
    if (o->roughness && o->request.quantity != QUANTITY_SPECULAR_OCCLUSION)
        return cli_failf("--roughness", "applies to specular-occlusion only"), -1;
    if (o->environment && o->request.quantity != QUANTITY_SPECULAR_OCCLUSION)
        return cli_failf("--environment", "applies to specular-occlusion only"), -1;
    if (!multibounce && (o->albedo || o->bounces))
        return cli_failf(o->albedo ? "--albedo" : "--bounces", "applies to multibounce only"), -1;
    if (!multibounce)
        return 0;
    if (!o->albedo)
        return cli_failf("render", "multibounce needs --albedo (grey albedos such as 0.1,0.5,0.9, or 'scene')"), -1;
    if (multibounce_parse_albedos(o->albedo, &o->request.multibounce, &e) != 0 ||
        (o->bounces && multibounce_parse_bounces(o->bounces, &o->request.multibounce, &e) != 0))
        return cli_fail(&e), -1;
    return 0;
}

static int parse_options(int argc, char **argv, render_options *o)
{
    static const struct option longs[] = {
        {"scene", required_argument, 0, 's'},      {"camera", required_argument, 0, 'c'},
        {"width", required_argument, 0, 'W'},      {"height", required_argument, 0, 'H'},
        {"spp", required_argument, 0, 'n'},        {"seed", required_argument, 0, 'S'},
        {"sample-offset", required_argument, 0, 'k'}, {"target-stderr", required_argument, 0, 'e'},
        {"max-distance", required_argument, 0, 'd'}, {"normal", required_argument, 0, 'N'},
        {"threads", required_argument, 0, 't'},    {"output", required_argument, 0, 'o'},
        {"albedo", required_argument, 0, 'a'},     {"bounces", required_argument, 0, 'b'},
        {"light-position", required_argument, 0, 'P'}, {"light-radius", required_argument, 0, 'R'},
        {"light-radiance", required_argument, 0, 'L'}, {"shadows", no_argument, 0, 'D'},
        {"roughness", required_argument, 0, 'r'}, {"environment", required_argument, 0, 'E'},
        {"help", no_argument, 0, 'h'},             {0, 0, 0, 0}};
    long value;
    double real;
    int c;
    while ((c = getopt_long(argc, argv, "o:h", longs, NULL)) != -1) {
        switch (c) {
        case 's': o->scene = optarg; break;
        case 'c': o->camera = optarg; break;
        case 'o': o->output = optarg; break;
        case 'W': if (cli_parse_int("--width", optarg, 1, 65536, &o->width)) return -1; break;
        case 'H': if (cli_parse_int("--height", optarg, 1, 65536, &o->height)) return -1; break;
        case 'n':
            if (cli_parse_int("--spp", optarg, 1, 1 << 24, &value)) return -1;
            o->request.sampling.spp = (int)value;
            break;
        case 'S': if (cli_parse_u32("--seed", optarg, &o->request.sampling.seed)) return -1; break;
        case 'k': if (cli_parse_u32("--sample-offset", optarg, &o->request.sampling.sample_offset)) return -1; break;
        case 'e':
            if (cli_parse_double("--target-stderr", optarg, 0.0, 1.0, &o->request.sampling.target_stderr)) return -1;
            break;
        case 'd':
            if (cli_parse_double("--max-distance", optarg, 1e-30, 1e30, &real)) return -1;
            o->request.max_distance = (float)real;
            o->max_distance = optarg;
            break;
        case 'a': o->albedo = optarg; break;
        case 'r':
            if (cli_parse_double("--roughness", optarg, 0.0, 1.0, &real)) return -1;
            o->request.roughness = (float)real;
            o->roughness = optarg;
            break;
        case 'E':
            if (environment_parse(optarg, &o->request.environment) != 0)
                return cli_failf("--environment", "'%s' is neither white nor sky", optarg), -1;
            o->environment = optarg;
            break;
        case 'b': o->bounces = optarg; break;
        case 'P': o->light_position = optarg; break;
        case 'R': o->light_radius = optarg; break;
        case 'L': o->light_radiance = optarg; break;
        case 'D': o->shadows = 1; break;
        case 't':
            if (cli_parse_int("--threads", optarg, 1, 1024, &value)) return -1;
            o->request.sampling.threads = (int)value;
            break;
        case 'N':
            if (strcmp(optarg, "shading") == 0)
                o->request.normals = NORMAL_SHADING;
            else if (strcmp(optarg, "geometric") == 0)
                o->request.normals = NORMAL_GEOMETRIC;
            else
                return cli_failf("--normal", "'%s' is neither shading nor geometric", optarg), -1;
            break;
        case 'h': print_help(); return 1;
        default: return cli_usage_error("render"), -1;
        }
    }
    if (optind >= argc)
        return cli_failf("render", "no QUANTITY given (gbuffer, ao, multibounce, heightfield-ao, specular-occlusion or sphere-light; see 'gtlab render --help')"), -1;
    if (reference_quantity_parse(argv[optind], &o->request.quantity) != 0)
        return cli_failf("render", "unknown quantity '%s' (gbuffer, ao, multibounce, heightfield-ao, specular-occlusion or sphere-light)", argv[optind]), -1;
    if (optind + 1 < argc)
        return cli_failf("render", "unexpected argument '%s'", argv[optind + 1]), -1;
    if (check_quantity_options(o) != 0 || check_light_options(o) != 0)
        return -1;
    if (!o->scene)
        return cli_failf("render", "--scene is required"), -1;
    if (!o->output)
        return cli_failf("render", "-o/--output is required"), -1;
    if ((uint64_t)o->request.sampling.sample_offset + (uint64_t)o->request.sampling.spp > 4294967296ull)
        return cli_failf("--sample-offset", "the block runs past sample index 2^32"), -1;
    return 0;
}

int verb_render(int argc, char **argv)
{
    render_options o = {0};
    o.request.sampling.spp = 64;
    o.request.sampling.seed = 1;
    o.request.sampling.threads = omp_get_num_procs();
    o.request.max_distance = INFINITY;
    o.request.roughness = -1.0f; /* the material's */
    o.request.multibounce.bounces = 4; /* the GTAO talk's */
    int parsed = parse_options(argc, argv, &o);
    if (parsed != 0)
        return parsed > 0 ? EXIT_OK : EXIT_USER_ERROR;

    gt_error e;
    char camera_path[ATOMIC_PATH_MAX];
    camera_sidecar_path(o.output, camera_path, sizeof camera_path);
    if (atomic_file_check_writable(o.output, &e) != 0 || atomic_file_check_writable(camera_path, &e) != 0)
        return cli_fail(&e);
    scene s;
    if (scene_load(o.scene, &s, &e) != 0)
        return cli_fail(&e);
    camera cam;
    image out;
    render_stats stats;
    int status = EXIT_OK;
    if (scene_choose_camera(&s, o.camera, (int)o.width, (int)o.height, &cam, &e) != 0 ||
        reference_render(&s, o.scene, &cam, &o.request, &out, &stats, &e) != 0) {
        status = cli_fail(&e);
    } else {
        if (exr_write(o.output, &out, &e) != 0 || camera_write_json(camera_path, &cam, &e) != 0)
            status = cli_fail(&e);
        else if (o.request.quantity != QUANTITY_GBUFFER)
            printf("%s: %dx%d, %.3g samples, %.3g rays in %.2f s (%.3g rays/s)\n", o.output,
                    cam.width, cam.height, (double)stats.samples, (double)stats.rays, stats.seconds,
                    stats.seconds > 0 ? (double)stats.rays / stats.seconds : 0.0);
        image_free(&out);
    }
    scene_free(&s);
    return status;
}
