/* aokit-c-sample: run one of aokit's AO techniques from plain C on Vulkan, using nothing of aokit
 * but its committed SPIR-V (the .spv files of assets/spirv/) and the generated headers
 * (assets/include/aokit.h, aokit_constants.h).
 *
 *   aokit-c-sample DIR TECHNIQUE OUT.pgm
 *
 * DIR is a frame written by `aokit export` (docs/export.md); TECHNIQUE is vao, gtao or raysd, at
 * its default settings; OUT.pgm receives the final AO of the inner image as a 16-bit binary PGM
 * (65535 = unoccluded). The passes, resources, sizes and fill values below are transcribed from
 * the `techniques` section of assets/spirv/manifest.json; binding slots and workgroup sizes come
 * from aokit.h, the push constants and records from aokit_constants.h. See examples/c/README.md.
 *
 * Environment: AOKIT_ASSETS (the assets/ folder; default: ../../../assets next to this
 * executable), AOKIT_C_VALIDATION=1 (Khronos validation layer; any message fails the run). */
#define _DEFAULT_SOURCE /* readlink */

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <vulkan/vulkan.h>

#include "aokit_constants.h"

/* ---------------------------------------------------------------------------------------------
 * Errors: one line on stderr, exit status 1. */

static _Noreturn void die(const char *fmt, ...) {
    va_list args;
    va_start(args, fmt);
    fputs("aokit-c-sample: ", stderr);
    vfprintf(stderr, fmt, args);
    fputc('\n', stderr);
    va_end(args);
    exit(1);
}

static const char *vk_result_name(VkResult r) {
    switch (r) {
    case VK_ERROR_OUT_OF_HOST_MEMORY: return "VK_ERROR_OUT_OF_HOST_MEMORY";
    case VK_ERROR_OUT_OF_DEVICE_MEMORY: return "VK_ERROR_OUT_OF_DEVICE_MEMORY";
    case VK_ERROR_INITIALIZATION_FAILED: return "VK_ERROR_INITIALIZATION_FAILED";
    case VK_ERROR_DEVICE_LOST: return "VK_ERROR_DEVICE_LOST";
    case VK_ERROR_LAYER_NOT_PRESENT: return "VK_ERROR_LAYER_NOT_PRESENT";
    case VK_ERROR_EXTENSION_NOT_PRESENT: return "VK_ERROR_EXTENSION_NOT_PRESENT";
    case VK_ERROR_FEATURE_NOT_PRESENT: return "VK_ERROR_FEATURE_NOT_PRESENT";
    case VK_ERROR_INCOMPATIBLE_DRIVER: return "VK_ERROR_INCOMPATIBLE_DRIVER";
    case VK_ERROR_INVALID_SHADER_NV: return "VK_ERROR_INVALID_SHADER_NV";
    default: return "VkResult";
    }
}

#define VK(call)                                                                                      \
    do {                                                                                              \
        VkResult vk_result_ = (call);                                                                 \
        if (vk_result_ != VK_SUCCESS)                                                                 \
            die("%s failed (%s %d)", #call, vk_result_name(vk_result_), (int)vk_result_);             \
    } while (0)

static void *xcalloc(size_t n, size_t size) {
    void *p = calloc(n ? n : 1, size ? size : 1);
    if (!p) die("out of memory");
    return p;
}

/* ---------------------------------------------------------------------------------------------
 * Files. */

/* `a/b` into `out` (n bytes). */
static void join_path(char *out, size_t n, const char *a, const char *b) {
    int len = snprintf(out, n, "%s/%s", a, b);
    if (len < 0 || (size_t)len >= n) die("path too long: %s/%s", a, b);
}

typedef struct {
    void *data;
    size_t size;
} Blob;

static Blob load(const char *dir, const char *name) {
    char path[PATH_MAX];
    join_path(path, sizeof path, dir, name);
    FILE *f = fopen(path, "rb");
    if (!f) die("cannot open %s: %s", path, strerror(errno));
    if (fseek(f, 0, SEEK_END) != 0) die("cannot read %s", path);
    long size = ftell(f);
    if (size < 0 || fseek(f, 0, SEEK_SET) != 0) die("cannot read %s", path);
    Blob b = {xcalloc((size_t)size + 1, 1), (size_t)size}; /* +1: text files end in '\0' */
    if (size > 0 && fread(b.data, 1, (size_t)size, f) != (size_t)size) die("cannot read %s", path);
    fclose(f);
    return b;
}

/* A file that must hold exactly `expected` bytes. */
static Blob load_sized(const char *dir, const char *name, size_t expected, const char *what) {
    Blob b = load(dir, name);
    if (b.size != expected)
        die("%s/%s: %zu bytes, expected %zu (%s)", dir, name, b.size, expected, what);
    return b;
}

/* The number after `"key":` in export.json (a minimal lookup: every key read here occurs once). */
static const char *json_value(const char *json, const char *key) {
    char pattern[64];
    snprintf(pattern, sizeof pattern, "\"%s\"", key);
    const char *p = strstr(json, pattern);
    if (!p) return NULL;
    p += strlen(pattern);
    while (*p == ' ' || *p == '\t' || *p == '\n' || *p == '\r') p++;
    if (*p != ':') return NULL;
    p++;
    while (*p == ' ' || *p == '\t' || *p == '\n' || *p == '\r') p++;
    return p;
}

static double json_number(const char *json, const char *key) {
    const char *p = json_value(json, key);
    char *end = NULL;
    double v = p ? strtod(p, &end) : 0.0;
    if (!p || end == p) die("export.json: no number \"%s\"", key);
    return v;
}

/* `"key": [a, b, …]`: `n` numbers. */
static void json_array(const char *json, const char *key, double *out, int n) {
    const char *p = json_value(json, key);
    if (!p || *p != '[') die("export.json: no array \"%s\"", key);
    p++;
    for (int i = 0; i < n; i++) {
        char *end = NULL;
        out[i] = strtod(p, &end);
        if (end == p) die("export.json: \"%s\" is not %d numbers", key, n);
        p = end;
        while (*p == ' ' || *p == ',') p++;
    }
}

static void json_pair(const char *json, const char *key, double out[2]) { json_array(json, key, out, 2); }

/* ---------------------------------------------------------------------------------------------
 * The frame: camera.bin, export.json and aokit's internal G-buffer. */

typedef struct {
    aokit_Camera camera;
    uint32_t W, H;    /* full target */
    uint32_t w, h;    /* inner image */
    uint32_t guard;   /* guard band on each side */
    float radius, exponent, thickness;
    /* What the constants' functions (aokit_constants.h) read: the camera as export.json gives it. */
    aokit_frame_inputs inputs;
    uint32_t triangles;
    Blob depth, normals; /* W·H f32 linear view depth, W·H u32 octahedral normals */
} Frame;

static Frame load_frame(const char *dir) {
    Frame f;
    memset(&f, 0, sizeof f);
    Blob json = load(dir, "export.json");
    const char *text = json.data;
    if (!strstr(text, "\"aokit-export/1\"")) die("%s/export.json: not format aokit-export/1", dir);
    double image[2];
    json_pair(text, "image", image);
    f.w = (uint32_t)image[0];
    f.h = (uint32_t)image[1];
    f.guard = (uint32_t)json_number(text, "guard_band");
    f.radius = (float)json_number(text, "radius");
    f.exponent = (float)json_number(text, "exponent");
    f.thickness = (float)json_number(text, "thickness");
    f.triangles = (uint32_t)json_number(text, "triangles");
    double eye[3], target[3], up[3];
    json_array(text, "eye", eye, 3);
    json_array(text, "target", target, 3);
    json_array(text, "up", up, 3);
    for (int i = 0; i < 3; i++) {
        f.inputs.eye[i] = (float)eye[i];
        f.inputs.target[i] = (float)target[i];
        f.inputs.up[i] = (float)up[i];
    }
    f.inputs.fov_y = (float)json_number(text, "fov_y"); /* radians, the binary32 the camera used */
    f.inputs.near_plane = (float)json_number(text, "near");
    f.inputs.far_plane = (float)json_number(text, "far");
    f.inputs.w = f.w;
    f.inputs.h = f.h;
    f.inputs.g = f.guard;
    f.inputs.radius = f.radius;
    f.inputs.exponent = f.exponent;
    f.inputs.thickness = f.thickness;
    f.inputs.frame = 0;
    free(json.data);

    Blob camera = load_sized(dir, "camera.bin", sizeof(aokit_Camera), "aokit_Camera");
    memcpy(&f.camera, camera.data, sizeof f.camera);
    free(camera.data);
    f.W = (uint32_t)f.camera.view.res.v[0];
    f.H = (uint32_t)f.camera.view.res.v[1];
    if (f.w == 0 || f.h == 0 || f.W != f.w + 2 * f.guard || f.H != f.h + 2 * f.guard ||
        f.camera.view.guard != f.guard)
        die("%s: camera.bin's target %ux%u (guard %u) does not match export.json's image %ux%u, guard %u", dir,
            f.W, f.H, f.camera.view.guard, f.w, f.h, f.guard);
    size_t texels = (size_t)f.W * f.H;
    f.depth = load_sized(dir, "gbuffer_depth.f32", 4 * texels, "full-target f32 depth");
    f.normals = load_sized(dir, "gbuffer_normals.u32", 4 * texels, "full-target u32 normals");
    return f;
}

/* The scene tables the ray-traced SD map reads (raysd only). */
typedef struct {
    Blob corners, uvs, materials, mask_headers, mask_texels;
} Scene;

static Scene load_scene(const char *dir, const Frame *f) {
    Scene s;
    size_t n = f->triangles;
    if (n == 0) die("%s/export.json: the scene has no triangles", dir);
    s.corners = load_sized(dir, "triangles.f32", 36 * n, "9 f32 per triangle");
    s.uvs = load_sized(dir, "uvs.f32", 24 * n, "6 f32 per triangle");
    s.materials = load_sized(dir, "materials.u32", 4 * n, "1 u32 per triangle");
    s.mask_headers = load(dir, "mask_headers.bin");
    if (s.mask_headers.size == 0 || s.mask_headers.size % sizeof(aokit_AlphaMaskHeader) != 0)
        die("%s/mask_headers.bin: %zu bytes, not a whole number of aokit_AlphaMaskHeader", dir, s.mask_headers.size);
    s.mask_texels = load(dir, "mask_texels.f32");
    if (s.mask_texels.size % 4 != 0) die("%s/mask_texels.f32: %zu bytes, not whole f32", dir, s.mask_texels.size);
    size_t materials = s.mask_headers.size / sizeof(aokit_AlphaMaskHeader);
    for (size_t i = 0; i < n; i++)
        if (((const uint32_t *)s.materials.data)[i] >= materials)
            die("%s/materials.u32: triangle %zu has material %u of %zu", dir, i,
                ((const uint32_t *)s.materials.data)[i], materials);
    return s;
}

/* ---------------------------------------------------------------------------------------------
 * A technique as data: resources (storage buffers of 4-byte words) and compute passes. */

#define MAX_RESOURCES 20
#define MAX_PASSES 16
#define MAX_BINDINGS 12
#define TLAS (-1) /* a binding of the acceleration structure instead of a resource */
#define ONE_F32 0x3f800000u

typedef struct {
    VkBuffer buffer;
    VkDeviceMemory memory;
    VkDeviceSize size;
    void *mapped; /* host-visible buffers only */
} Buffer;

typedef struct {
    const char *name;
    size_t words;
    enum { INIT_FILL, INIT_DATA, INIT_UNDEFINED } init;
    uint32_t fill;
    const void *data; /* INIT_DATA: `data_bytes` bytes, the rest zero */
    size_t data_bytes;
    Buffer buffer;
} Resource;

typedef struct {
    uint32_t slot;
    int resource; /* index into Graph.resources, or TLAS */
} Binding;

typedef struct {
    char entry[64];    /* the module's entry point = its file stem */
    const char *file;  /* AOKIT_<MODULE>_SPV */
    uint32_t workgroup[2];
    uint32_t invocations[2];
    bool barrier_before; /* the manifest's barrier_before */
    uint32_t push_bytes;
    unsigned char push[128];
    uint32_t bindings;
    Binding binding[MAX_BINDINGS];
} Pass;

typedef struct {
    Resource resources[MAX_RESOURCES];
    unsigned n_resources;
    Pass passes[MAX_PASSES];
    unsigned n_passes;
    int output;
    bool ray_query; /* needs the TLAS and VK_KHR_ray_query */
} Graph;

static int add_resource(Graph *g, const char *name, size_t words, uint32_t fill) {
    if (g->n_resources == MAX_RESOURCES) die("too many resources");
    Resource *r = &g->resources[g->n_resources];
    memset(r, 0, sizeof *r);
    r->name = name;
    r->words = words;
    r->init = INIT_FILL;
    r->fill = fill;
    return (int)g->n_resources++;
}

static int add_data(Graph *g, const char *name, const void *data, size_t bytes) {
    int i = add_resource(g, name, (bytes + 3) / 4, 0);
    g->resources[i].init = INIT_DATA;
    g->resources[i].data = data;
    g->resources[i].data_bytes = bytes;
    return i;
}

/* `module` is AOKIT_<MODULE>_SPV; `push` the push-constant struct (NULL: none). */
static Pass *add_pass(Graph *g, const char *module, uint32_t wg_x, uint32_t wg_y, uint32_t inv_x, uint32_t inv_y,
                      const void *push, uint32_t push_bytes) {
    if (g->n_passes == MAX_PASSES) die("too many passes");
    Pass *p = &g->passes[g->n_passes];
    memset(p, 0, sizeof *p);
    p->file = module;
    snprintf(p->entry, sizeof p->entry, "%s", module);
    char *dot = strstr(p->entry, ".spv");
    if (dot) *dot = '\0';
    p->workgroup[0] = wg_x;
    p->workgroup[1] = wg_y;
    p->invocations[0] = inv_x;
    p->invocations[1] = inv_y;
    /* Every pass of vao, gtao and raysd but the first has barrier_before: true. */
    p->barrier_before = g->n_passes > 0;
    if (push_bytes > sizeof p->push) die("push constants too large");
    if (push) memcpy(p->push, push, push_bytes);
    p->push_bytes = push_bytes;
    g->n_passes++;
    return p;
}

static void bind(Pass *p, uint32_t slot, int resource) {
    if (p->bindings == MAX_BINDINGS) die("too many bindings");
    p->binding[p->bindings].slot = slot;
    p->binding[p->bindings].resource = resource;
    p->bindings++;
}

#define MODULE(M) AOKIT_##M##_SPV, AOKIT_##M##_WORKGROUP_X, AOKIT_##M##_WORKGROUP_Y

/* --- Constants: aokit_constants.h's functions, generated from the manifest's expressions (each
 * technique at its defaults; `pass` is the pass's index among its module's passes). */

/* The cross-bilateral blur of `input` into a new resource ao_final (blur_horizontal between);
 * `bp` the two passes' BlurParams. */
static int add_blur(Graph *g, const Frame *f, int depth, int input, const aokit_BlurParams bp[2]) {
    int scratch = add_resource(g, "blur_horizontal", (size_t)f->W * f->H, ONE_F32);
    int output = add_resource(g, "ao_final", (size_t)f->W * f->H, ONE_F32);
    const int from[2] = {input, scratch}, to[2] = {scratch, output};
    for (int i = 0; i < 2; i++) {
        Pass *p = add_pass(g, MODULE(BLUR_MAIN), f->w, f->h, &bp[i], sizeof bp[i]);
        bind(p, AOKIT_BLUR_MAIN_BINDING_AO_IN, from[i]);
        bind(p, AOKIT_BLUR_MAIN_BINDING_DEPTH, depth);
        bind(p, AOKIT_BLUR_MAIN_BINDING_AO_OUT, to[i]);
    }
    return output;
}

/* vao: vao_main over the inner image, then the blur. */
static void graph_vao(Graph *g, const Frame *f) {
    int depth = add_data(g, "linear_depth", f->depth.data, f->depth.size);
    int normals = add_data(g, "view_normals", f->normals.data, f->normals.size);
    int ao = add_resource(g, "ao", (size_t)f->W * f->H, ONE_F32);
    aokit_vao_settings s = aokit_vao_defaults();
    aokit_VaoParams vp;
    aokit_vao_VaoParams(&s, &f->inputs, 0, &vp);
    Pass *p = add_pass(g, MODULE(VAO_MAIN), f->w, f->h, &vp, sizeof vp);
    bind(p, AOKIT_VAO_MAIN_BINDING_DEPTH, depth);
    bind(p, AOKIT_VAO_MAIN_BINDING_NORMALS, normals);
    bind(p, AOKIT_VAO_MAIN_BINDING_AO, ao);
    aokit_BlurParams bp[2];
    for (uint32_t i = 0; i < 2; i++) aokit_vao_BlurParams(&s, &f->inputs, i, &bp[i]);
    g->output = add_blur(g, f, depth, ao, bp);
}

/* gtao (preset high: 3 slices × 3 steps, 1 denoise pass): 2 prefilter passes, main pass, denoise. */
#define GTAO_MIP_LEVELS 5u
static uint32_t div_ceil(uint32_t a, uint32_t b) { return (a + b - 1) / b; }
static uint32_t mip_extent(uint32_t full, uint32_t level) {
    uint32_t e = full >> level;
    return e ? e : 1; /* max(1, floor(full / 2^level)) */
}

static void graph_gtao(Graph *g, const Frame *f) {
    int depth = add_data(g, "linear_depth", f->depth.data, f->depth.size);
    int normals = add_data(g, "view_normals", f->normals.data, f->normals.size);
    size_t mip_words = 0;
    for (uint32_t l = 0; l < GTAO_MIP_LEVELS; l++) mip_words += (size_t)mip_extent(f->W, l) * mip_extent(f->H, l);
    size_t texels = (size_t)f->W * f->H;
    int mips = add_resource(g, "gtao_mips", mip_words, 0);
    g->resources[mips].init = INIT_UNDEFINED;
    int terms = add_resource(g, "gtao_terms", texels, 0);
    int edges = add_resource(g, "gtao_edges", texels, 0);
    int ping = add_resource(g, "denoise_ping", texels, 0);
    int pong = add_resource(g, "denoise_pong", texels, 0);
    int output = add_resource(g, "ao_final", texels, ONE_F32);

    aokit_gtao_settings s = aokit_gtao_defaults();
    aokit_GtaoParams gp;
    aokit_gtao_GtaoParams(&s, &f->inputs, 0, &gp);

    /* prefilter: pass 0 over 2×2 blocks (MIPs 0–1), pass 1 over 16×16 blocks (MIPs 2–4). */
    const uint32_t block[2] = {2, 16};
    for (uint32_t pass = 0; pass < 2; pass++) {
        aokit_gtao_GtaoParams(&s, &f->inputs, pass, &gp);
        Pass *p = add_pass(g, MODULE(GTAO_PREFILTER), div_ceil(f->W, block[pass]), div_ceil(f->H, block[pass]), &gp,
                           sizeof gp);
        bind(p, AOKIT_GTAO_PREFILTER_BINDING_DEPTH, depth);
        bind(p, AOKIT_GTAO_PREFILTER_BINDING_MIPS, mips);
    }
    aokit_gtao_GtaoParams(&s, &f->inputs, 0, &gp);
    Pass *p = add_pass(g, MODULE(GTAO_MAIN), f->W, f->H, &gp, sizeof gp);
    bind(p, AOKIT_GTAO_MAIN_BINDING_MIPS, mips);
    bind(p, AOKIT_GTAO_MAIN_BINDING_NORMALS, normals);
    bind(p, AOKIT_GTAO_MAIN_BINDING_TERMS, terms);
    bind(p, AOKIT_GTAO_MAIN_BINDING_EDGES, edges);
    /* max(1, denoise_passes) passes ping-ponging; each writes the visibility into ao_final. */
    int from = terms, to = ping;
    for (uint32_t i = 0; i < (gp.denoise_passes ? gp.denoise_passes : 1); i++) {
        aokit_gtao_GtaoParams(&s, &f->inputs, i, &gp); /* denoise: pass = its index */
        p = add_pass(g, MODULE(GTAO_DENOISE), div_ceil(f->W, 2), f->H, &gp, sizeof gp); /* pixel pairs */
        bind(p, AOKIT_GTAO_DENOISE_BINDING_TERMS_IN, from);
        bind(p, AOKIT_GTAO_DENOISE_BINDING_EDGES, edges);
        bind(p, AOKIT_GTAO_DENOISE_BINDING_TERMS_OUT, to);
        bind(p, AOKIT_GTAO_DENOISE_BINDING_AO, output);
        from = to;
        to = to == ping ? pong : ping;
    }
    g->output = output;
}

/* raysd at its defaults (SD map at ¼ resolution, 4 layers, single depth, VAO kernel):
 * svao_pass1 → SD map (ray queries) → raysd_pass2 → blur. */
static void graph_raysd(Graph *g, const Frame *f, const Scene *sc, aokit_SvaoFrame *svao) {
    aokit_raysd_settings s = aokit_raysd_defaults();
    aokit_raysd_SvaoFrame(&s, &f->inputs, 0, svao);
    const aokit_SvaoParams *sp = &svao->params;
    /* SD texels: the low-res map plus its guard band on each side. */
    uint32_t sd_w = sp->sd_low_res.v[0] + 2 * sp->sd_guard, sd_h = sp->sd_low_res.v[1] + 2 * sp->sd_guard;
    size_t sd_texels = (size_t)sd_w * sd_h, texels = (size_t)f->W * f->H;

    g->ray_query = true;
    int frame = add_data(g, "svao_frame", svao, sizeof *svao);
    int depth = add_data(g, "linear_depth", f->depth.data, f->depth.size);
    int normals = add_data(g, "view_normals", f->normals.data, f->normals.size);
    int uvs = add_data(g, "scene_uvs", sc->uvs.data, sc->uvs.size);
    int materials = add_data(g, "scene_materials", sc->materials.data, sc->materials.size);
    int headers = add_data(g, "scene_mask_headers", sc->mask_headers.data, sc->mask_headers.size);
    int texels_ = add_data(g, "scene_mask_texels", sc->mask_texels.data, sc->mask_texels.size);
    int ao = add_resource(g, "ao", texels, ONE_F32);
    int mask = add_resource(g, "refine_mask", texels, 0);
    int ray_min = add_resource(g, "ray_min", sd_texels, 0x7f7fffffu);
    int ray_max = add_resource(g, "ray_max", sd_texels, 0);
    int sd_map = add_resource(g, "sd_map", sd_texels * sp->sd_layers, ONE_F32);
    int ray_count = add_resource(g, "ray_count", 2, 0); /* rays traced: u64 as (low, high) */

    Pass *p = add_pass(g, MODULE(SVAO_PASS1), f->w, f->h, NULL, 0);
    bind(p, AOKIT_SVAO_PASS1_BINDING_FRAME, frame);
    bind(p, AOKIT_SVAO_PASS1_BINDING_DEPTH, depth);
    bind(p, AOKIT_SVAO_PASS1_BINDING_NORMALS, normals);
    bind(p, AOKIT_SVAO_PASS1_BINDING_AO, ao);
    bind(p, AOKIT_SVAO_PASS1_BINDING_MASK, mask);
    bind(p, AOKIT_SVAO_PASS1_BINDING_RAY_MIN, ray_min);
    bind(p, AOKIT_SVAO_PASS1_BINDING_RAY_MAX, ray_max);
    bind(p, AOKIT_SVAO_PASS1_BINDING_DEPTH2, depth); /* single depth: the depth buffer (unread) */

    /* The SD map: the manifest's ray-tracing pass raysd_rgen (+ raysd_miss, raysd_ahit) as its
     * ray-query compute variant raysd_rq, over the same launch size. */
    p = add_pass(g, MODULE(RAYSD_RQ), sd_w, sd_h, NULL, 0);
    bind(p, AOKIT_RAYSD_RQ_BINDING_FRAME, frame);
    bind(p, AOKIT_RAYSD_RQ_BINDING_TLAS, TLAS);
    bind(p, AOKIT_RAYSD_RQ_BINDING_DEPTH, depth);
    /* Slot 3 (the manifest's view_normals) is not declared by the module: nothing to bind. */
    bind(p, AOKIT_RAYSD_RQ_BINDING_RAY_MIN, ray_min);
    bind(p, AOKIT_RAYSD_RQ_BINDING_RAY_MAX, ray_max);
    bind(p, AOKIT_RAYSD_RQ_BINDING_SD_MAP, sd_map);
    bind(p, AOKIT_RAYSD_RQ_BINDING_UVS, uvs);
    bind(p, AOKIT_RAYSD_RQ_BINDING_MATERIALS, materials);
    bind(p, AOKIT_RAYSD_RQ_BINDING_MASK_HEADERS, headers);
    bind(p, AOKIT_RAYSD_RQ_BINDING_MASK_TEXELS, texels_);
    bind(p, AOKIT_RAYSD_RQ_BINDING_RAY_COUNT, ray_count);

    p = add_pass(g, MODULE(RAYSD_PASS2), f->w, f->h, NULL, 0);
    bind(p, AOKIT_RAYSD_PASS2_BINDING_FRAME, frame);
    bind(p, AOKIT_RAYSD_PASS2_BINDING_DEPTH, depth);
    bind(p, AOKIT_RAYSD_PASS2_BINDING_NORMALS, normals);
    bind(p, AOKIT_RAYSD_PASS2_BINDING_AO, ao);
    bind(p, AOKIT_RAYSD_PASS2_BINDING_MASK, mask);
    bind(p, AOKIT_RAYSD_PASS2_BINDING_SD_MAP, sd_map);
    bind(p, AOKIT_RAYSD_PASS2_BINDING_DEPTH2, depth);

    aokit_BlurParams bp[2];
    for (uint32_t i = 0; i < 2; i++) aokit_raysd_BlurParams(&s, &f->inputs, i, &bp[i]);
    g->output = add_blur(g, f, depth, ao, bp);
}

/* ---------------------------------------------------------------------------------------------
 * SPIR-V modules: assets/spirv/ from AOKIT_ASSETS or relative to this executable. */

static void spirv_dir(char *out, size_t n, const char *argv0) {
    const char *assets = getenv("AOKIT_ASSETS");
    if (assets && *assets) {
        join_path(out, n, assets, "spirv");
        return;
    }
    char exe[PATH_MAX];
    ssize_t len = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (len > 0) {
        exe[len] = '\0';
    } else {
        snprintf(exe, sizeof exe, "%s", argv0);
    }
    char *slash = strrchr(exe, '/');
    if (slash) {
        *slash = '\0';
    } else {
        snprintf(exe, sizeof exe, ".");
    }
    join_path(out, n, exe, "../../../assets/spirv");
}

static Blob load_spirv(const char *dir, const char *file) {
    char path[PATH_MAX];
    join_path(path, sizeof path, dir, file);
    FILE *f = fopen(path, "rb");
    if (!f) die("missing SPIR-V module %s (%s; set AOKIT_ASSETS to aokit's assets/ folder)", path, strerror(errno));
    fclose(f);
    Blob b = load(dir, file);
    if (b.size < 20 || b.size % 4 != 0 || ((const uint32_t *)b.data)[0] != 0x07230203u)
        die("%s: not a SPIR-V module", path);
    return b;
}

/* ---------------------------------------------------------------------------------------------
 * Vulkan. */

typedef struct {
    VkInstance instance;
    VkDebugUtilsMessengerEXT messenger;
    VkPhysicalDevice physical;
    VkPhysicalDeviceProperties properties;
    VkPhysicalDeviceMemoryProperties memory;
    VkDevice device;
    uint32_t family;
    VkQueue queue;
    VkCommandPool pool;
    bool ray_query;
    VkDeviceSize scratch_alignment;
    PFN_vkCreateAccelerationStructureKHR create_as;
    PFN_vkDestroyAccelerationStructureKHR destroy_as;
    PFN_vkGetAccelerationStructureBuildSizesKHR build_sizes;
    PFN_vkCmdBuildAccelerationStructuresKHR cmd_build_as;
    PFN_vkGetAccelerationStructureDeviceAddressKHR as_address;
} Gpu;

static unsigned validation_messages;

static VKAPI_ATTR VkBool32 VKAPI_CALL on_validation(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                    VkDebugUtilsMessageTypeFlagsEXT type,
                                                    const VkDebugUtilsMessengerCallbackDataEXT *data, void *user) {
    (void)type;
    (void)user;
    if (severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) {
        validation_messages++;
        fprintf(stderr, "aokit-c-sample: validation: %s\n", data->pMessage);
    }
    return VK_FALSE;
}

static bool has_extension(const VkExtensionProperties *list, uint32_t n, const char *name) {
    for (uint32_t i = 0; i < n; i++)
        if (strcmp(list[i].extensionName, name) == 0) return true;
    return false;
}

static bool env_on(const char *name) {
    const char *v = getenv(name);
    return v && strcmp(v, "1") == 0;
}

static void create_instance(Gpu *g) {
    bool validation = env_on("AOKIT_C_VALIDATION");
    const char *layers[1] = {"VK_LAYER_KHRONOS_validation"};
    const char *extensions[2];
    uint32_t n_extensions = 0;
    bool sync_validation = false;
    if (validation) {
        uint32_t n = 0;
        vkEnumerateInstanceLayerProperties(&n, NULL);
        VkLayerProperties *list = xcalloc(n, sizeof *list);
        vkEnumerateInstanceLayerProperties(&n, list);
        bool found = false;
        for (uint32_t i = 0; i < n; i++) found |= strcmp(list[i].layerName, layers[0]) == 0;
        free(list);
        if (!found)
            die("AOKIT_C_VALIDATION=1 but VK_LAYER_KHRONOS_validation is not installed "
                "(Debian: apt-get install vulkan-validationlayers)");
        extensions[n_extensions++] = VK_EXT_DEBUG_UTILS_EXTENSION_NAME;
        uint32_t m = 0;
        vkEnumerateInstanceExtensionProperties(layers[0], &m, NULL);
        VkExtensionProperties *ext = xcalloc(m, sizeof *ext);
        vkEnumerateInstanceExtensionProperties(layers[0], &m, ext);
        if (has_extension(ext, m, VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME)) {
            extensions[n_extensions++] = VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME;
            sync_validation = true;
        }
        free(ext);
    }
    VkDebugUtilsMessengerCreateInfoEXT messenger = {
        .sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT,
        .messageSeverity =
            VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT,
        .messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT,
        .pfnUserCallback = on_validation,
    };
    /* Synchronization validation checks the barriers between passes too. */
    const VkValidationFeatureEnableEXT enables[1] = {VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
    VkValidationFeaturesEXT features = {
        .sType = VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT,
        .pNext = &messenger,
        .enabledValidationFeatureCount = 1,
        .pEnabledValidationFeatures = enables,
    };
    VkApplicationInfo app = {
        .sType = VK_STRUCTURE_TYPE_APPLICATION_INFO,
        .pApplicationName = "aokit-c-sample",
        .apiVersion = VK_API_VERSION_1_2, /* the modules are SPIR-V 1.5, the Vulkan 1.2 target */
    };
    VkInstanceCreateInfo info = {
        .sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO,
        .pNext = validation ? (sync_validation ? (const void *)&features : (const void *)&messenger) : NULL,
        .pApplicationInfo = &app,
        .enabledLayerCount = validation ? 1 : 0,
        .ppEnabledLayerNames = layers,
        .enabledExtensionCount = n_extensions,
        .ppEnabledExtensionNames = extensions,
    };
    VkResult r = vkCreateInstance(&info, NULL, &g->instance);
    if (r != VK_SUCCESS)
        die("no Vulkan device: vkCreateInstance failed (%s %d); is a Vulkan driver installed (e.g. Mesa's lavapipe: "
            "apt-get install mesa-vulkan-drivers)?",
            vk_result_name(r), (int)r);
    if (validation) {
        PFN_vkCreateDebugUtilsMessengerEXT create = (PFN_vkCreateDebugUtilsMessengerEXT)vkGetInstanceProcAddr(
            g->instance, "vkCreateDebugUtilsMessengerEXT");
        if (!create) die("vkCreateDebugUtilsMessengerEXT missing");
        messenger.pNext = NULL;
        VK(create(g->instance, &messenger, NULL, &g->messenger));
    }
}

static const char *const RAY_QUERY_EXTENSIONS[3] = {
    VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME,
    VK_KHR_RAY_QUERY_EXTENSION_NAME,
    VK_KHR_DEFERRED_HOST_OPERATIONS_EXTENSION_NAME,
};

/* Whether `pd` can run the modules (Vulkan 1.2, the Vulkan memory model, a compute queue; ray
 * queries when asked); its compute queue family in `family`. */
static bool suitable(VkPhysicalDevice pd, bool ray_query, uint32_t *family) {
    VkPhysicalDeviceProperties props;
    vkGetPhysicalDeviceProperties(pd, &props);
    if (props.apiVersion < VK_API_VERSION_1_2) return false;
    uint32_t n = 0;
    vkEnumerateDeviceExtensionProperties(pd, NULL, &n, NULL);
    VkExtensionProperties *ext = xcalloc(n, sizeof *ext);
    vkEnumerateDeviceExtensionProperties(pd, NULL, &n, ext);
    bool extensions = true;
    for (int i = 0; i < 3; i++) extensions &= has_extension(ext, n, RAY_QUERY_EXTENSIONS[i]);
    free(ext);
    if (ray_query && !extensions) return false;

    VkPhysicalDeviceRayQueryFeaturesKHR rq = {.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_QUERY_FEATURES_KHR};
    VkPhysicalDeviceAccelerationStructureFeaturesKHR as = {
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR, .pNext = &rq};
    VkPhysicalDeviceVulkan12Features v12 = {.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES,
                                            .pNext = ray_query ? (void *)&as : NULL};
    VkPhysicalDeviceFeatures2 f2 = {.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, .pNext = &v12};
    vkGetPhysicalDeviceFeatures2(pd, &f2);
    if (!v12.vulkanMemoryModel || !v12.vulkanMemoryModelDeviceScope) return false;
    if (ray_query && (!v12.bufferDeviceAddress || !as.accelerationStructure || !rq.rayQuery)) return false;

    vkGetPhysicalDeviceQueueFamilyProperties(pd, &n, NULL);
    VkQueueFamilyProperties *families = xcalloc(n, sizeof *families);
    vkGetPhysicalDeviceQueueFamilyProperties(pd, &n, families);
    bool found = false;
    for (uint32_t i = 0; i < n && !found; i++) {
        if (families[i].queueFlags & VK_QUEUE_COMPUTE_BIT) {
            *family = i;
            found = true;
        }
    }
    free(families);
    return found;
}

static void create_device(Gpu *g, bool ray_query) {
    uint32_t n = 0;
    VkResult r = vkEnumeratePhysicalDevices(g->instance, &n, NULL);
    if (r != VK_SUCCESS) die("no Vulkan device: vkEnumeratePhysicalDevices failed (%s %d)", vk_result_name(r), (int)r);
    if (n == 0) die("no Vulkan device (a driver, e.g. Mesa's lavapipe: apt-get install mesa-vulkan-drivers)");
    VkPhysicalDevice *devices = xcalloc(n, sizeof *devices);
    VK(vkEnumeratePhysicalDevices(g->instance, &n, devices));
    /* The first suitable device of the best type: discrete, integrated, virtual, CPU. */
    static const VkPhysicalDeviceType preference[5] = {
        VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU, VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU,
        VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU, VK_PHYSICAL_DEVICE_TYPE_CPU, VK_PHYSICAL_DEVICE_TYPE_OTHER};
    bool chosen = false;
    for (int t = 0; t < 5 && !chosen; t++) {
        for (uint32_t i = 0; i < n && !chosen; i++) {
            VkPhysicalDeviceProperties props;
            vkGetPhysicalDeviceProperties(devices[i], &props);
            if (props.deviceType == preference[t] && suitable(devices[i], ray_query, &g->family)) {
                g->physical = devices[i];
                chosen = true;
            }
        }
    }
    free(devices);
    if (!chosen)
        die("no Vulkan device with Vulkan 1.2, vulkanMemoryModel and vulkanMemoryModelDeviceScope%s",
            ray_query ? ", VK_KHR_ray_query and VK_KHR_acceleration_structure (raysd traces rays)" : "");
    vkGetPhysicalDeviceProperties(g->physical, &g->properties);
    vkGetPhysicalDeviceMemoryProperties(g->physical, &g->memory);

    /* rust-gpu always emits the Vulkan memory model; raysd adds ray queries on a TLAS built from
     * device addresses. */
    VkPhysicalDeviceRayQueryFeaturesKHR rq = {.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_QUERY_FEATURES_KHR,
                                              .rayQuery = VK_TRUE};
    VkPhysicalDeviceAccelerationStructureFeaturesKHR as = {
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR,
        .pNext = &rq,
        .accelerationStructure = VK_TRUE};
    VkPhysicalDeviceVulkan12Features v12 = {
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES,
        .pNext = ray_query ? (void *)&as : NULL,
        .bufferDeviceAddress = ray_query ? VK_TRUE : VK_FALSE,
        .vulkanMemoryModel = VK_TRUE,
        .vulkanMemoryModelDeviceScope = VK_TRUE,
    };
    VkPhysicalDeviceFeatures2 features = {.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, .pNext = &v12};
    float priority = 1.0f;
    VkDeviceQueueCreateInfo queue = {
        .sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO,
        .queueFamilyIndex = g->family,
        .queueCount = 1,
        .pQueuePriorities = &priority,
    };
    VkDeviceCreateInfo info = {
        .sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO,
        .pNext = &features,
        .queueCreateInfoCount = 1,
        .pQueueCreateInfos = &queue,
        .enabledExtensionCount = ray_query ? 3 : 0,
        .ppEnabledExtensionNames = RAY_QUERY_EXTENSIONS,
    };
    VK(vkCreateDevice(g->physical, &info, NULL, &g->device));
    vkGetDeviceQueue(g->device, g->family, 0, &g->queue);
    VkCommandPoolCreateInfo pool = {.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO,
                                    .queueFamilyIndex = g->family};
    VK(vkCreateCommandPool(g->device, &pool, NULL, &g->pool));

    g->ray_query = ray_query;
    if (ray_query) {
        VkPhysicalDeviceAccelerationStructurePropertiesKHR asp = {
            .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_PROPERTIES_KHR};
        VkPhysicalDeviceProperties2 p2 = {.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, .pNext = &asp};
        vkGetPhysicalDeviceProperties2(g->physical, &p2);
        g->scratch_alignment = asp.minAccelerationStructureScratchOffsetAlignment;
        if (g->scratch_alignment == 0) g->scratch_alignment = 1;
#define LOAD(field, name)                                                                                     \
    g->field = (PFN_##name)vkGetDeviceProcAddr(g->device, #name);                                              \
    if (!g->field) die(#name " missing")
        LOAD(create_as, vkCreateAccelerationStructureKHR);
        LOAD(destroy_as, vkDestroyAccelerationStructureKHR);
        LOAD(build_sizes, vkGetAccelerationStructureBuildSizesKHR);
        LOAD(cmd_build_as, vkCmdBuildAccelerationStructuresKHR);
        LOAD(as_address, vkGetAccelerationStructureDeviceAddressKHR);
#undef LOAD
    }
}

/* A buffer with its own allocation. `host`: mapped, host-visible and coherent (device-local too
 * where such memory exists); otherwise device-local where possible. */
static Buffer buffer_new(Gpu *g, VkDeviceSize size, VkBufferUsageFlags usage, bool host) {
    Buffer b;
    memset(&b, 0, sizeof b);
    b.size = size < 4 ? 4 : (size + 3) & ~(VkDeviceSize)3; /* Vulkan has no empty buffers */
    VkBufferCreateInfo info = {.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO, .size = b.size, .usage = usage};
    VK(vkCreateBuffer(g->device, &info, NULL, &b.buffer));
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(g->device, b.buffer, &req);
    VkMemoryPropertyFlags need = host ? VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT : 0;
    VkMemoryPropertyFlags want = need | VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
    uint32_t type = UINT32_MAX;
    for (int pass = 0; pass < 2 && type == UINT32_MAX; pass++) {
        VkMemoryPropertyFlags flags = pass == 0 ? want : need;
        for (uint32_t i = 0; i < g->memory.memoryTypeCount && type == UINT32_MAX; i++)
            if ((req.memoryTypeBits & (1u << i)) && (g->memory.memoryTypes[i].propertyFlags & flags) == flags) type = i;
    }
    if (type == UINT32_MAX) die("no memory type for a %s buffer", host ? "host-visible" : "device");
    VkMemoryAllocateFlagsInfo flags = {.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_FLAGS_INFO,
                                       .flags = VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT};
    VkMemoryAllocateInfo alloc = {
        .sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO,
        .pNext = (usage & VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT) ? &flags : NULL,
        .allocationSize = req.size,
        .memoryTypeIndex = type,
    };
    VK(vkAllocateMemory(g->device, &alloc, NULL, &b.memory));
    VK(vkBindBufferMemory(g->device, b.buffer, b.memory, 0));
    if (host) VK(vkMapMemory(g->device, b.memory, 0, VK_WHOLE_SIZE, 0, &b.mapped));
    return b;
}

static void buffer_free(Gpu *g, Buffer *b) {
    if (b->mapped) vkUnmapMemory(g->device, b->memory);
    vkDestroyBuffer(g->device, b->buffer, NULL);
    vkFreeMemory(g->device, b->memory, NULL);
    memset(b, 0, sizeof *b);
}

static VkDeviceAddress buffer_address(Gpu *g, const Buffer *b) {
    VkBufferDeviceAddressInfo info = {.sType = VK_STRUCTURE_TYPE_BUFFER_DEVICE_ADDRESS_INFO, .buffer = b->buffer};
    return vkGetBufferDeviceAddress(g->device, &info);
}

static void memory_barrier(VkCommandBuffer cb, VkPipelineStageFlags src_stage, VkAccessFlags src_access,
                           VkPipelineStageFlags dst_stage, VkAccessFlags dst_access) {
    VkMemoryBarrier barrier = {
        .sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER,
        .srcAccessMask = src_access,
        .dstAccessMask = dst_access,
    };
    vkCmdPipelineBarrier(cb, src_stage, dst_stage, 0, 1, &barrier, 0, NULL, 0, NULL);
}

/* ---------------------------------------------------------------------------------------------
 * The scene's acceleration structures: one BLAS of every triangle (one geometry, no index
 * buffer, not opaque) and a TLAS with one identity instance whose custom index is 0, the first
 * triangle's index in the uvs/materials tables. */

typedef struct {
    VkAccelerationStructureKHR handle;
    Buffer storage, scratch;
} Accel;

static Accel accel_build(Gpu *g, VkCommandBuffer cb, VkAccelerationStructureTypeKHR type,
                         const VkAccelerationStructureGeometryKHR *geometry, uint32_t primitives) {
    VkAccelerationStructureBuildGeometryInfoKHR info = {
        .sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR,
        .type = type,
        .flags = VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR,
        .mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR,
        .geometryCount = 1,
        .pGeometries = geometry,
    };
    VkAccelerationStructureBuildSizesInfoKHR sizes = {
        .sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR};
    g->build_sizes(g->device, VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR, &info, &primitives, &sizes);
    Accel a;
    memset(&a, 0, sizeof a);
    a.storage = buffer_new(g, sizes.accelerationStructureSize,
                           VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_STORAGE_BIT_KHR |
                               VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
                           false);
    VkAccelerationStructureCreateInfoKHR create = {
        .sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_CREATE_INFO_KHR,
        .buffer = a.storage.buffer,
        .size = sizes.accelerationStructureSize,
        .type = type,
    };
    VK(g->create_as(g->device, &create, NULL, &a.handle));
    a.scratch = buffer_new(g, sizes.buildScratchSize + g->scratch_alignment,
                           VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT, false);
    VkDeviceAddress scratch = buffer_address(g, &a.scratch);
    scratch = (scratch + g->scratch_alignment - 1) / g->scratch_alignment * g->scratch_alignment;
    info.dstAccelerationStructure = a.handle;
    info.scratchData.deviceAddress = scratch;
    VkAccelerationStructureBuildRangeInfoKHR range = {.primitiveCount = primitives};
    const VkAccelerationStructureBuildRangeInfoKHR *ranges = &range;
    g->cmd_build_as(cb, 1, &info, &ranges);
    return a;
}

typedef struct {
    Accel blas, tlas;
    Buffer vertices, instance;
} SceneAccel;

/* Records the builds into `cb`; the buffers live until the command buffer completed. */
static SceneAccel scene_accel(Gpu *g, VkCommandBuffer cb, const Scene *s, uint32_t triangles) {
    SceneAccel sa;
    const VkBufferUsageFlags input =
        VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR |
        VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;
    sa.vertices = buffer_new(g, s->corners.size, input, true);
    memcpy(sa.vertices.mapped, s->corners.data, s->corners.size);
    VkAccelerationStructureGeometryKHR blas_geometry = {
        .sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR,
        .geometryType = VK_GEOMETRY_TYPE_TRIANGLES_KHR,
        .geometry.triangles =
            {
                .sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_TRIANGLES_DATA_KHR,
                .vertexFormat = VK_FORMAT_R32G32B32_SFLOAT,
                .vertexData.deviceAddress = buffer_address(g, &sa.vertices),
                .vertexStride = 12,
                .maxVertex = 3 * triangles - 1,
                .indexType = VK_INDEX_TYPE_NONE_KHR,
            },
        /* Not OPAQUE: alpha-masked materials need the candidate loop (Ray-SD also traces
         * with NO_OPAQUE, so it sees every triangle either way). */
        .flags = 0,
    };
    sa.blas = accel_build(g, cb, VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR, &blas_geometry, triangles);
    memory_barrier(cb, VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
                   VK_ACCESS_ACCELERATION_STRUCTURE_WRITE_BIT_KHR,
                   VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
                   VK_ACCESS_ACCELERATION_STRUCTURE_READ_BIT_KHR);

    VkAccelerationStructureDeviceAddressInfoKHR address = {
        .sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_DEVICE_ADDRESS_INFO_KHR,
        .accelerationStructure = sa.blas.handle};
    VkAccelerationStructureInstanceKHR instance = {
        .transform = {.matrix = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}}},
        .instanceCustomIndex = 0, /* the index of the BLAS's first triangle in uvs/materials */
        .mask = 0xff,
        .instanceShaderBindingTableRecordOffset = 0,
        .flags = VK_GEOMETRY_INSTANCE_TRIANGLE_FACING_CULL_DISABLE_BIT_KHR,
        .accelerationStructureReference = g->as_address(g->device, &address),
    };
    sa.instance = buffer_new(g, sizeof instance, input, true);
    memcpy(sa.instance.mapped, &instance, sizeof instance);
    VkAccelerationStructureGeometryKHR tlas_geometry = {
        .sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR,
        .geometryType = VK_GEOMETRY_TYPE_INSTANCES_KHR,
        .geometry.instances =
            {
                .sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_INSTANCES_DATA_KHR,
                .arrayOfPointers = VK_FALSE,
                .data.deviceAddress = buffer_address(g, &sa.instance),
            },
    };
    sa.tlas = accel_build(g, cb, VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR, &tlas_geometry, 1);
    /* The compute passes' ray queries read the TLAS. */
    memory_barrier(cb, VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
                   VK_ACCESS_ACCELERATION_STRUCTURE_WRITE_BIT_KHR, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                   VK_ACCESS_ACCELERATION_STRUCTURE_READ_BIT_KHR);
    return sa;
}

static void scene_accel_free(Gpu *g, SceneAccel *sa) {
    Accel *both[2] = {&sa->tlas, &sa->blas};
    for (int i = 0; i < 2; i++) {
        g->destroy_as(g->device, both[i]->handle, NULL);
        buffer_free(g, &both[i]->storage);
        buffer_free(g, &both[i]->scratch);
    }
    buffer_free(g, &sa->vertices);
    buffer_free(g, &sa->instance);
}

/* ---------------------------------------------------------------------------------------------
 * Pipelines: one per module (entry point), its set layout from the first pass that uses it. */

typedef struct {
    const char *entry;
    VkShaderModule module;
    VkDescriptorSetLayout set_layout;
    VkPipelineLayout layout;
    VkPipeline pipeline;
} Pipeline;

static Pipeline pipeline_new(Gpu *g, const Pass *pass, const Blob *spirv) {
    Pipeline p;
    memset(&p, 0, sizeof p);
    p.entry = pass->entry;
    VkShaderModuleCreateInfo module = {
        .sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO, .codeSize = spirv->size, .pCode = spirv->data};
    VK(vkCreateShaderModule(g->device, &module, NULL, &p.module));
    VkDescriptorSetLayoutBinding bindings[MAX_BINDINGS];
    for (uint32_t i = 0; i < pass->bindings; i++) {
        bindings[i] = (VkDescriptorSetLayoutBinding){
            .binding = pass->binding[i].slot,
            .descriptorType = pass->binding[i].resource == TLAS ? VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR
                                                                : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
            .descriptorCount = 1,
            .stageFlags = VK_SHADER_STAGE_COMPUTE_BIT,
        };
    }
    VkDescriptorSetLayoutCreateInfo set = {
        .sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO,
        .bindingCount = pass->bindings,
        .pBindings = bindings,
    };
    VK(vkCreateDescriptorSetLayout(g->device, &set, NULL, &p.set_layout));
    VkPushConstantRange range = {.stageFlags = VK_SHADER_STAGE_COMPUTE_BIT, .offset = 0, .size = pass->push_bytes};
    VkPipelineLayoutCreateInfo layout = {
        .sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO,
        .setLayoutCount = 1,
        .pSetLayouts = &p.set_layout,
        .pushConstantRangeCount = pass->push_bytes ? 1 : 0,
        .pPushConstantRanges = &range,
    };
    VK(vkCreatePipelineLayout(g->device, &layout, NULL, &p.layout));
    VkComputePipelineCreateInfo info = {
        .sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO,
        .stage =
            {
                .sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
                .stage = VK_SHADER_STAGE_COMPUTE_BIT,
                .module = p.module,
                .pName = pass->entry,
            },
        .layout = p.layout,
    };
    VK(vkCreateComputePipelines(g->device, VK_NULL_HANDLE, 1, &info, NULL, &p.pipeline));
    return p;
}

static void pipeline_free(Gpu *g, Pipeline *p) {
    vkDestroyPipeline(g->device, p->pipeline, NULL);
    vkDestroyPipelineLayout(g->device, p->layout, NULL);
    vkDestroyDescriptorSetLayout(g->device, p->set_layout, NULL);
    vkDestroyShaderModule(g->device, p->module, NULL);
}

/* ---------------------------------------------------------------------------------------------
 * Output. */

/* Written to a temporary file next to PATH, flushed to disk and renamed over PATH: a run killed or
 * failing half-way leaves the old file or none, never a truncated one (as aokit's own outputs). */
static void write_pgm(const char *path, const float *ao_full, const Frame *f) {
    char tmp[PATH_MAX];
    int n = snprintf(tmp, sizeof tmp, "%s.%ld.aokit-tmp", path, (long)getpid());
    if (n < 0 || (size_t)n >= sizeof tmp) die("cannot write %s: path too long", path);
    FILE *out = fopen(tmp, "wb");
    if (!out) die("cannot write %s: %s", path, strerror(errno));
    bool ok = fprintf(out, "P5\n%u %u\n65535\n", f->w, f->h) > 0;
    for (uint32_t y = f->guard; ok && y < f->H - f->guard; y++) {
        for (uint32_t x = f->guard; ok && x < f->W - f->guard; x++) {
            float v = ao_full[(size_t)y * f->W + x];
            v = v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f; /* NaN → 0 */
            uint16_t s = (uint16_t)lrintf(v * 65535.0f);
            unsigned char be[2] = {(unsigned char)(s >> 8), (unsigned char)(s & 0xff)};
            ok = fwrite(be, 1, 2, out) == 2;
        }
    }
    ok = ok && fflush(out) == 0 && fsync(fileno(out)) == 0;
    int err = ok ? 0 : errno;
    if (fclose(out) != 0 && ok) {
        ok = false;
        err = errno;
    }
    if (ok && rename(tmp, path) != 0) {
        ok = false;
        err = errno;
    }
    if (!ok) {
        remove(tmp);
        die("cannot write %s: %s", path, strerror(err));
    }
}

/* ---------------------------------------------------------------------------------------------
 * main. */

int main(int argc, char **argv) {
    if (argc != 4) {
        fprintf(stderr, "usage: %s DIR vao|gtao|raysd OUT.pgm\n", argc > 0 ? argv[0] : "aokit-c-sample");
        return 1;
    }
    const char *dir = argv[1], *technique = argv[2], *out_path = argv[3];
    if (strcmp(technique, "vao") != 0 && strcmp(technique, "gtao") != 0 && strcmp(technique, "raysd") != 0)
        die("unknown technique \"%s\" (vao, gtao or raysd)", technique);

    /* Inputs, then the technique's graph, then its modules: every file error before Vulkan. */
    Frame frame = load_frame(dir);
    Scene scene;
    memset(&scene, 0, sizeof scene);
    static Graph graph;
    static aokit_SvaoFrame svao;
    if (strcmp(technique, "vao") == 0) {
        graph_vao(&graph, &frame);
    } else if (strcmp(technique, "gtao") == 0) {
        graph_gtao(&graph, &frame);
    } else {
        scene = load_scene(dir, &frame);
        graph_raysd(&graph, &frame, &scene, &svao);
    }
    char spirv[PATH_MAX];
    spirv_dir(spirv, sizeof spirv, argv[0]);
    Blob code[MAX_PASSES];
    for (unsigned i = 0; i < graph.n_passes; i++) code[i] = load_spirv(spirv, graph.passes[i].file);

    Gpu gpu;
    memset(&gpu, 0, sizeof gpu);
    create_instance(&gpu);
    create_device(&gpu, graph.ray_query);

    /* Storage buffers, filled as the manifest's `init` says. */
    for (unsigned i = 0; i < graph.n_resources; i++) {
        Resource *r = &graph.resources[i];
        r->buffer = buffer_new(&gpu, 4 * (VkDeviceSize)r->words, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, true);
        uint32_t *words = r->buffer.mapped;
        memset(words, 0, r->buffer.size);
        if (r->init == INIT_FILL) {
            for (size_t k = 0; k < r->words; k++) words[k] = r->fill;
        } else if (r->init == INIT_DATA) {
            memcpy(words, r->data, r->data_bytes);
        }
    }

    /* Pipelines and one descriptor set per pass. */
    Pipeline pipelines[MAX_PASSES];
    unsigned n_pipelines = 0;
    Pipeline *pass_pipeline[MAX_PASSES];
    uint32_t storage_descriptors = 0, tlas_descriptors = 0;
    for (unsigned i = 0; i < graph.n_passes; i++) {
        const Pass *pass = &graph.passes[i];
        Pipeline *found = NULL;
        for (unsigned k = 0; k < n_pipelines && !found; k++)
            if (strcmp(pipelines[k].entry, pass->entry) == 0) found = &pipelines[k];
        if (!found) {
            pipelines[n_pipelines] = pipeline_new(&gpu, pass, &code[i]);
            found = &pipelines[n_pipelines++];
        }
        pass_pipeline[i] = found;
        for (uint32_t b = 0; b < pass->bindings; b++) {
            if (pass->binding[b].resource == TLAS) {
                tlas_descriptors++;
            } else {
                storage_descriptors++;
            }
        }
    }
    VkDescriptorPoolSize sizes[2] = {
        {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, storage_descriptors},
        {VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR, tlas_descriptors},
    };
    VkDescriptorPoolCreateInfo pool_info = {
        .sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO,
        .maxSets = graph.n_passes,
        .poolSizeCount = tlas_descriptors ? 2 : 1,
        .pPoolSizes = sizes,
    };
    VkDescriptorPool pool;
    VK(vkCreateDescriptorPool(gpu.device, &pool_info, NULL, &pool));

    VkCommandBuffer cb;
    VkCommandBufferAllocateInfo cb_info = {
        .sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
        .commandPool = gpu.pool,
        .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY,
        .commandBufferCount = 1,
    };
    VK(vkAllocateCommandBuffers(gpu.device, &cb_info, &cb));
    VkCommandBufferBeginInfo begin = {.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                      .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
    VK(vkBeginCommandBuffer(cb, &begin));
    SceneAccel accel;
    memset(&accel, 0, sizeof accel);
    if (graph.ray_query) accel = scene_accel(&gpu, cb, &scene, frame.triangles);

    VkDescriptorSet sets[MAX_PASSES];
    for (unsigned i = 0; i < graph.n_passes; i++) {
        const Pass *pass = &graph.passes[i];
        VkDescriptorSetAllocateInfo alloc = {
            .sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO,
            .descriptorPool = pool,
            .descriptorSetCount = 1,
            .pSetLayouts = &pass_pipeline[i]->set_layout,
        };
        VK(vkAllocateDescriptorSets(gpu.device, &alloc, &sets[i]));
        VkWriteDescriptorSet writes[MAX_BINDINGS];
        VkDescriptorBufferInfo buffers[MAX_BINDINGS];
        VkWriteDescriptorSetAccelerationStructureKHR tlas = {
            .sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET_ACCELERATION_STRUCTURE_KHR,
            .accelerationStructureCount = 1,
            .pAccelerationStructures = &accel.tlas.handle,
        };
        for (uint32_t b = 0; b < pass->bindings; b++) {
            const Binding *binding = &pass->binding[b];
            writes[b] = (VkWriteDescriptorSet){
                .sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
                .dstSet = sets[i],
                .dstBinding = binding->slot,
                .descriptorCount = 1,
            };
            if (binding->resource == TLAS) {
                writes[b].pNext = &tlas;
                writes[b].descriptorType = VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR;
            } else {
                buffers[b] = (VkDescriptorBufferInfo){graph.resources[binding->resource].buffer.buffer, 0,
                                                      VK_WHOLE_SIZE};
                writes[b].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
                writes[b].pBufferInfo = &buffers[b];
            }
        }
        vkUpdateDescriptorSets(gpu.device, pass->bindings, writes, 0, NULL);
    }

    /* The passes in order; a barrier (shader writes → shader reads and writes) before every pass
     * the manifest marks barrier_before. */
    for (unsigned i = 0; i < graph.n_passes; i++) {
        const Pass *pass = &graph.passes[i];
        if (pass->barrier_before)
            memory_barrier(cb, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
                           VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                           VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
        vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_COMPUTE, pass_pipeline[i]->pipeline);
        vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_COMPUTE, pass_pipeline[i]->layout, 0, 1, &sets[i], 0,
                                NULL);
        if (pass->push_bytes)
            vkCmdPushConstants(cb, pass_pipeline[i]->layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, pass->push_bytes,
                               pass->push);
        vkCmdDispatch(cb, (pass->invocations[0] + pass->workgroup[0] - 1) / pass->workgroup[0],
                      (pass->invocations[1] + pass->workgroup[1] - 1) / pass->workgroup[1], 1);
    }
    /* The host reads the output through its mapping. */
    memory_barrier(cb, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT,
                   VK_ACCESS_HOST_READ_BIT);
    VK(vkEndCommandBuffer(cb));

    VkFence fence;
    VkFenceCreateInfo fence_info = {.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VK(vkCreateFence(gpu.device, &fence_info, NULL, &fence));
    VkSubmitInfo submit = {.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO, .commandBufferCount = 1, .pCommandBuffers = &cb};
    VK(vkQueueSubmit(gpu.queue, 1, &submit, fence));
    VK(vkWaitForFences(gpu.device, 1, &fence, VK_TRUE, UINT64_MAX));

    write_pgm(out_path, graph.resources[graph.output].buffer.mapped, &frame);
    printf("%s: %ux%u inner image (target %ux%u), %u passes on %s -> %s\n", technique, frame.w, frame.h, frame.W,
           frame.H, graph.n_passes, gpu.properties.deviceName, out_path);

    /* Everything back (the validation layer reports leaks). */
    vkDestroyFence(gpu.device, fence, NULL);
    vkDestroyDescriptorPool(gpu.device, pool, NULL);
    for (unsigned i = 0; i < n_pipelines; i++) pipeline_free(&gpu, &pipelines[i]);
    if (graph.ray_query) scene_accel_free(&gpu, &accel);
    for (unsigned i = 0; i < graph.n_resources; i++) buffer_free(&gpu, &graph.resources[i].buffer);
    vkDestroyCommandPool(gpu.device, gpu.pool, NULL);
    vkDestroyDevice(gpu.device, NULL);
    if (gpu.messenger) {
        PFN_vkDestroyDebugUtilsMessengerEXT destroy = (PFN_vkDestroyDebugUtilsMessengerEXT)vkGetInstanceProcAddr(
            gpu.instance, "vkDestroyDebugUtilsMessengerEXT");
        if (destroy) destroy(gpu.instance, gpu.messenger, NULL);
    }
    vkDestroyInstance(gpu.instance, NULL);
    for (unsigned i = 0; i < graph.n_passes; i++) free(code[i].data);
    free(frame.depth.data);
    free(frame.normals.data);
    Blob *tables[5] = {&scene.corners, &scene.uvs, &scene.materials, &scene.mask_headers, &scene.mask_texels};
    for (int i = 0; i < 5; i++) free(tables[i]->data);
    if (validation_messages) die("the validation layer reported %u message(s)", validation_messages);
    return 0;
}
