/* embree_anyhit.c — Embree 4 traces the rays of an `aokit rays --dump DIR` folder on P pthreads
 * (for bench/rays_vs_embree.sh): the G-buffer's primary rays (rtcIntersect1), the ground
 * truth's AO rays (rtcOccluded1), and the any-hit rays of the SD map and of Ray-SVAO
 * (rtcIntersect1 with an intersection filter doing the kernels' any-hit: valid[0] = 0 rejects a
 * candidate and traversal goes on over the same interval, as IGNORE does; a kept candidate is
 * committed and tfar shrinks to it, as ACCEPT does). No Python, no GIL: P threads trace one
 * scene, taking chunks of 4,096 rays from a shared counter.
 *
 *   gcc -O2 -ffp-contract=off -o embree_anyhit bench/embree_anyhit.c -l:libembree4-….so.4 -lpthread -lm
 *   ./embree_anyhit DIR [--threads 2] [--repeat 3] [--json OUT]
 *   ./embree_anyhit --replay IN OUT     (no Embree: the any-hit decisions on given candidates)
 *
 * There are no Embree headers on the machine (the embreex wheel ships only the library): the
 * declarations below are the few functions, enums and structs of Embree 4's documented API that
 * this file needs. Layouts: RTCRay is 48 bytes (org, tnear, dir, time, tfar, mask, id, flags),
 * RTCHit follows it (Ng, u, v, primID, geomID, instID[1], instPrimID[1] in 4.3+; 48 bytes
 * reserved here); a filter function sees one ray (N = 1) with the candidate's distance in its
 * tfar and the candidate's u, v, primID at hit floats 3, 4 and 5. The closest-hit answers are
 * checked against cpu-sim's (same triangle on all but shared-edge rays), which checks this
 * layout; the build is Embree's default (medium quality, no scene flags), as embreex's.
 *
 * The any-hit decisions are a C port of the kernels' (aokit_shaders::raysd::reservoir_slot,
 * reservoir_candidate, reservoir_commit with wyman_hash, rotate and sat; aokit_shaders::raysvao::
 * sample_any_hit), for this benchmark only; `--replay` runs them on candidates from a file so
 * that tests/rays.rs checks them bit for bit against the Rust kernels. Every triangle counts as
 * opaque for the alpha test (Embree gets no textures): compare with `aokit rays --alpha off` on
 * scenes with masks. */

#define _GNU_SOURCE
#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* ---- the kernels' any-hit decisions (C port, see above) ---- */

#define MAX_LAYERS 8
#define NO_SLOT 0xffffffffu
#define IGNORE 0u
#define ACCEPT 1u
#define ACCEPT_AND_END 2u

/* aokit_shaders::raysd::SdPayload (#[repr(C)]). */
typedef struct SdPayload {
    float depth[MAX_LAYERS];
    uint32_t count, layers, max_count;
    float cos_theta, near, far, rotation;
} SdPayload;

/* aokit_shaders::raysvao::SampleRayState (#[repr(C)]). */
typedef struct SampleState {
    float t_halo, t_inside, t_const, t_sphere;
} SampleState;

static inline float frac_(float x) { return x - floorf(x); }
/* crate::common::math::sat: x > 0 ? (x < 1 ? x : 1) : 0 (NaN → 0). */
static inline float sat_(float x) { return x > 0.0f ? (x < 1.0f ? x : 1.0f) : 0.0f; }
static inline float wyman_hash(float u, float v) {
    return frac_(1.0e4f * sinf(17.0f * u + 0.1f * v) * (0.1f + fabsf(sinf(13.0f * v + u))));
}

/* SdHits::decide with every triangle passing the alpha test. */
static uint32_t sd_decide(SdPayload *p, float t, float bu, float bv) {
    float u = frac_(wyman_hash(bu, bv) + p->rotation);
    float z = sat_((t * p->cos_theta - p->near) / (p->far - p->near));
    uint32_t slot = p->count;
    p->count += 1;
    if (p->count > p->layers) slot = (uint32_t)(u * (float)p->count);
    if (slot >= p->layers || p->depth[slot] <= z) slot = NO_SLOT;
    if (slot != NO_SLOT) p->depth[slot] = z;
    return p->count >= p->max_count ? ACCEPT : IGNORE;
}

/* SampleHits::decide with every triangle passing the alpha test (sample_any_hit). */
static uint32_t svao_decide(SampleState *s, float t) {
    if (t < s->t_halo) return IGNORE;
    if (t <= s->t_sphere) {
        s->t_halo = s->t_halo > t ? s->t_halo : t;
        return t >= s->t_const ? ACCEPT_AND_END : IGNORE;
    }
    s->t_inside = s->t_inside < t ? s->t_inside : t;
    return ACCEPT;
}

static void die(const char *msg, const char *what) {
    fprintf(stderr, "embree_anyhit: %s%s%s\n", msg, what ? ": " : "", what ? what : "");
    exit(1);
}

/* --replay IN OUT: IN holds records [u32 kind (0 SD, 1 Ray-SVAO), u32 n, the starting
 * SdPayload (60 bytes) or SampleState (16 bytes), n × f32 (t, u, v)]: n candidates, all beyond
 * the ray's t_min, offered in order as a traversal offers them — one at or beyond the distance
 * of an accepted candidate is skipped, nothing after ACCEPT_AND_END is offered. OUT gets each
 * record's final payload or state (aokit_cpu::bvh::replay_any_hit's semantics). */
static int replay(const char *in_path, const char *out_path) {
    FILE *in = fopen(in_path, "rb"), *out = fopen(out_path, "wb");
    if (!in || !out) die("cannot open", in ? out_path : in_path);
    uint32_t head[2];
    while (fread(head, 4, 2, in) == 2) {
        SdPayload p;
        SampleState s;
        if (head[0] == 0 ? fread(&p, sizeof p, 1, in) != 1 : fread(&s, sizeof s, 1, in) != 1) die("short record", in_path);
        float t_max = INFINITY;
        int ended = 0;
        for (uint32_t i = 0; i < head[1]; i++) {
            float c[3];
            if (fread(c, 4, 3, in) != 3) die("short candidate", in_path);
            if (ended || !(c[0] < t_max)) continue;
            uint32_t d = head[0] == 0 ? sd_decide(&p, c[0], c[1], c[2]) : svao_decide(&s, c[0]);
            if (d != IGNORE) t_max = c[0];
            if (d == ACCEPT_AND_END) ended = 1;
        }
        if (head[0] == 0 ? fwrite(&p, sizeof p, 1, out) != 1 : fwrite(&s, sizeof s, 1, out) != 1) die("write", out_path);
    }
    fclose(in);
    return fclose(out) == 0 ? 0 : 1;
}

#ifndef AOKIT_NO_EMBREE

/* ---- Embree 4 (declarations from the documented API) ---- */

typedef struct RTCDeviceTy *RTCDevice;
typedef struct RTCSceneTy *RTCScene;
typedef struct RTCGeometryTy *RTCGeometry;
enum { RTC_GEOMETRY_TYPE_TRIANGLE = 0 };
enum { RTC_BUFFER_TYPE_INDEX = 0, RTC_BUFFER_TYPE_VERTEX = 1 };
enum { RTC_FORMAT_UINT3 = 0x5003, RTC_FORMAT_FLOAT3 = 0x9003 };
#define RTC_INVALID_GEOMETRY_ID 0xffffffffu

typedef struct __attribute__((aligned(16))) RTCRay {
    float org_x, org_y, org_z, tnear;
    float dir_x, dir_y, dir_z, time;
    float tfar;
    unsigned int mask, id, flags;
} RTCRay;

typedef struct __attribute__((aligned(16))) RTCHit {
    float Ng_x, Ng_y, Ng_z, u, v;
    unsigned int primID, geomID, instID[1];
    unsigned int reserved[4]; /* instPrimID[1] where the library has instance arrays */
} RTCHit;

typedef struct RTCRayHit {
    RTCRay ray;
    RTCHit hit;
} RTCRayHit;

typedef struct RTCFilterFunctionNArguments {
    int *valid;
    void *geometryUserPtr;
    const void *context;
    void *ray; /* RTCRayN: for N = 1 an RTCRay */
    void *hit; /* RTCHitN: for N = 1 the fields of RTCHit */
    unsigned int N;
} RTCFilterFunctionNArguments;
typedef void (*RTCFilterFunctionN)(const RTCFilterFunctionNArguments *args);

RTCDevice rtcNewDevice(const char *config);
void rtcReleaseDevice(RTCDevice device);
int rtcGetDeviceError(RTCDevice device);
RTCScene rtcNewScene(RTCDevice device);
void rtcReleaseScene(RTCScene scene);
RTCGeometry rtcNewGeometry(RTCDevice device, int type);
void *rtcSetNewGeometryBuffer(RTCGeometry geometry, int type, unsigned int slot, int format, size_t byteStride,
                              size_t itemCount);
void rtcSetGeometryIntersectFilterFunction(RTCGeometry geometry, RTCFilterFunctionN filter);
void rtcCommitGeometry(RTCGeometry geometry);
unsigned int rtcAttachGeometry(RTCScene scene, RTCGeometry geometry);
void rtcReleaseGeometry(RTCGeometry geometry);
void rtcCommitScene(RTCScene scene);
/* The arguments pointer is optional (NULL: the defaults). */
void rtcIntersect1(RTCScene scene, RTCRayHit *rayhit, void *args);
void rtcOccluded1(RTCScene scene, RTCRay *ray, void *args);

/* ---- .npy files written by aokit::rays::write_npy (version 1.0, little-endian, C order) ---- */

typedef struct Array {
    void *data;
    size_t count; /* elements */
    size_t rows;  /* the first dimension */
} Array;

static Array load_npy(const char *dir, const char *name, const char *descr, size_t elem) {
    char path[4096];
    snprintf(path, sizeof path, "%s/%s.npy", dir, name);
    FILE *f = fopen(path, "rb");
    if (!f) die("cannot open", path);
    unsigned char pre[10];
    if (fread(pre, 1, 10, f) != 10 || memcmp(pre, "\x93NUMPY\x01\x00", 8) != 0) die("not a .npy 1.0 file", path);
    size_t hlen = pre[8] | (pre[9] << 8);
    char *header = calloc(hlen + 1, 1);
    if (fread(header, 1, hlen, f) != hlen) die("short header", path);
    char want[64];
    snprintf(want, sizeof want, "'descr': '%s'", descr);
    if (!strstr(header, want)) die("unexpected element type", path);
    const char *shape = strstr(header, "'shape': (");
    if (!shape) die("no shape", path);
    shape += 10;
    size_t count = 1, rows = 0;
    for (int dim = 0; *shape && *shape != ')'; dim++) {
        char *end;
        size_t d = strtoul(shape, &end, 10);
        if (end == shape) break;
        if (dim == 0) rows = d;
        count *= d;
        shape = end;
        while (*shape == ',' || *shape == ' ') shape++;
    }
    free(header);
    Array a = {malloc(count * elem + 1), count, rows};
    if (fread(a.data, elem, count, f) != count) die("short payload", path);
    fclose(f);
    return a;
}

/* ---- the work ---- */

enum Kind { PRIMARY, AO, SD, SVAO, KINDS };
static const char *kind_name[KINDS] = {"primary", "ao", "sd", "svao"};

typedef struct Work {
    RTCScene plain, filtered;
    size_t n[KINDS];
    float eye[3];
    const float *primary_dir, *ao_org, *ao_dir, *ao_tmax;
    const float *sd_dir, *sd_interval, *sd_cos, *sv_dir, *sv_interval, *sv_state;
    SdPayload sd_proto; /* N, MAX_COUNT, near, far, rotation */
    /* Answers. */
    int32_t *primary_hit;
    float *primary_t;
    uint8_t *ao_occluded;
    SdPayload *sd_out;
    SampleState *sv_out;
} Work;

/* The filter's view of the ray being traced on this thread. */
static __thread int current_kind;
static __thread void *current_payload;
static __thread int current_ended;

static void any_hit_filter(const RTCFilterFunctionNArguments *args) {
    const float *ray = args->ray, *hit = args->hit;
    float t = ray[8]; /* tfar holds the candidate's distance */
    if (current_ended) {
        args->valid[0] = 0;
        return;
    }
    uint32_t d = current_kind == SD ? sd_decide(current_payload, t, hit[3], hit[4]) : svao_decide(current_payload, t);
    if (d == IGNORE) args->valid[0] = 0;
    /* ACCEPT_AND_END: Embree cannot end an rtcIntersect1 from a filter; the hit is committed
     * (tfar shrinks to it) and every later candidate is rejected, so the state stays as ended. */
    if (d == ACCEPT_AND_END) current_ended = 1;
}

static void trace_one(Work *w, enum Kind kind, size_t i) {
    if (kind == AO) {
        RTCRay r = {w->ao_org[3 * i], w->ao_org[3 * i + 1], w->ao_org[3 * i + 2], 0.0f,
                    w->ao_dir[3 * i], w->ao_dir[3 * i + 1], w->ao_dir[3 * i + 2], 0.0f,
                    w->ao_tmax[i], 0xffffffffu, 0, 0};
        rtcOccluded1(w->plain, &r, NULL);
        w->ao_occluded[i] = r.tfar == -INFINITY; /* Embree sets tfar to −∞ when occluded */
        return;
    }
    const float *dir = kind == PRIMARY ? w->primary_dir : kind == SD ? w->sd_dir : w->sv_dir;
    RTCRayHit rh;
    memset(&rh, 0, sizeof rh);
    rh.ray = (RTCRay){w->eye[0], w->eye[1], w->eye[2], 0.0f, dir[3 * i], dir[3 * i + 1], dir[3 * i + 2], 0.0f,
                      INFINITY, 0xffffffffu, 0, 0};
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    if (kind == PRIMARY) {
        rtcIntersect1(w->plain, &rh, NULL);
        int hit = rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
        w->primary_hit[i] = hit ? (int32_t)rh.hit.primID : -1;
        w->primary_t[i] = hit ? rh.ray.tfar : INFINITY;
        return;
    }
    const float *iv = kind == SD ? w->sd_interval : w->sv_interval;
    rh.ray.tnear = iv[2 * i];
    rh.ray.tfar = iv[2 * i + 1];
    current_kind = kind;
    current_ended = 0;
    if (kind == SD) {
        w->sd_out[i] = w->sd_proto;
        w->sd_out[i].cos_theta = w->sd_cos[i];
        current_payload = &w->sd_out[i];
    } else {
        memcpy(&w->sv_out[i], &w->sv_state[4 * i], sizeof(SampleState));
        current_payload = &w->sv_out[i];
    }
    rtcIntersect1(w->filtered, &rh, NULL);
}

#define CHUNK 4096

typedef struct Pool {
    Work *w;
    int threads;
    enum Kind kind;
    atomic_size_t next;
    pthread_barrier_t start, done;
    int quit;
} Pool;

static void run_chunks(Pool *p) {
    size_t n = p->w->n[p->kind];
    for (;;) {
        size_t lo = atomic_fetch_add(&p->next, CHUNK);
        if (lo >= n) break;
        size_t hi = lo + CHUNK < n ? lo + CHUNK : n;
        for (size_t i = lo; i < hi; i++) trace_one(p->w, p->kind, i);
    }
}

static void *worker(void *arg) {
    Pool *p = arg;
    for (;;) {
        pthread_barrier_wait(&p->start);
        if (p->quit) return NULL;
        run_chunks(p);
        pthread_barrier_wait(&p->done);
    }
}

static double now(clockid_t clock) {
    struct timespec ts;
    clock_gettime(clock, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static void stats_json(FILE *f, const char *name, size_t rays, const double *wall, const double *cpu, int repeat) {
    double best = 1e30, sorted[64], cpu_sum = 0.0;
    for (int r = 0; r < repeat; r++) {
        best = wall[r] < best ? wall[r] : best;
        sorted[r] = wall[r];
        cpu_sum += cpu[r];
    }
    for (int a = 1; a < repeat; a++)
        for (int b = a; b > 0 && sorted[b - 1] > sorted[b]; b--) {
            double t = sorted[b];
            sorted[b] = sorted[b - 1];
            sorted[b - 1] = t;
        }
    double median = repeat % 2 ? sorted[repeat / 2] : 0.5 * (sorted[repeat / 2 - 1] + sorted[repeat / 2]);
    fprintf(f, "\"%s\": {\"rays\": %zu, \"runs_s\": [", name, rays);
    for (int r = 0; r < repeat; r++) fprintf(f, "%s%.6f", r ? ", " : "", wall[r]);
    fprintf(f, "], \"cpu_s\": [");
    for (int r = 0; r < repeat; r++) fprintf(f, "%s%.6f", r ? ", " : "", cpu[r]);
    fprintf(f, "], \"min_s\": %.6f, \"median_s\": %.6f, \"mrays_per_s_best\": %.4f, \"mrays_per_s_median\": %.4f, "
               "\"mrays_per_cpu_s\": %.4f",
            best, median, rays / best / 1e6, rays / median / 1e6, cpu_sum > 0 ? rays * repeat / cpu_sum / 1e6 : 0.0);
}

/* The number of the first `layers` depths below 1 (filled slots). */
static int filled(const float *depth, int layers) {
    int k = 0;
    for (int l = 0; l < layers; l++) k += depth[l] < 1.0f;
    return k;
}

/* A number from rays.json: the value after "key": inside the object that follows "section". */
static double json_number(const char *text, const char *section, const char *key) {
    const char *s = strstr(text, section);
    if (!s) die("rays.json has no", section);
    const char *k = strstr(s, key);
    if (!k) die("rays.json has no", key);
    k = strchr(k, ':');
    return strtod(k + 1, NULL);
}

int main(int argc, char **argv) {
    if (argc == 4 && strcmp(argv[1], "--replay") == 0) return replay(argv[2], argv[3]);
    if (argc < 2) die("usage: embree_anyhit DIR [--threads P] [--repeat R] [--json OUT] | --replay IN OUT", NULL);
    const char *dir = argv[1], *json_path = NULL;
    int threads = 2, repeat = 3;
    for (int a = 2; a < argc; a++) {
        if (strcmp(argv[a], "--threads") == 0 && a + 1 < argc) threads = atoi(argv[++a]);
        else if (strcmp(argv[a], "--repeat") == 0 && a + 1 < argc) repeat = atoi(argv[++a]);
        else if (strcmp(argv[a], "--json") == 0 && a + 1 < argc) json_path = argv[++a];
        else die("unknown argument", argv[a]);
    }
    if (threads < 1 || repeat < 1 || repeat > 64) die("--threads ≥ 1 and 1 ≤ --repeat ≤ 64", NULL);

    /* rays.json: the eye and the SD reservoir's constants. */
    char path[4096];
    snprintf(path, sizeof path, "%s/rays.json", dir);
    FILE *jf = fopen(path, "rb");
    if (!jf) die("cannot open", path);
    static char text[1 << 20];
    size_t len = fread(text, 1, sizeof text - 1, jf);
    text[len] = 0;
    fclose(jf);

    Work w;
    memset(&w, 0, sizeof w);
    const char *eye = strstr(text, "\"eye\"");
    if (!eye || sscanf(strchr(eye, '[') + 1, "%f , %f , %f", &w.eye[0], &w.eye[1], &w.eye[2]) != 3) die("rays.json: no eye", NULL);
    for (int l = 0; l < MAX_LAYERS; l++) w.sd_proto.depth[l] = 1.0f;
    w.sd_proto.layers = (uint32_t)json_number(text, "\"sd\":", "\"layers\"");
    w.sd_proto.max_count = (uint32_t)json_number(text, "\"sd\":", "\"max_count\"");
    w.sd_proto.near = (float)json_number(text, "\"sd\":", "\"near\"");
    w.sd_proto.far = (float)json_number(text, "\"sd\":", "\"far\"");
    w.sd_proto.rotation = (float)json_number(text, "\"sd\":", "\"rotation\"");
    int layers = (int)w.sd_proto.layers;

    Array tris = load_npy(dir, "triangles", "<f4", 4);
    Array pdir = load_npy(dir, "primary_directions", "<f4", 4), phit = load_npy(dir, "primary_hits", "<i4", 4);
    Array pt = load_npy(dir, "primary_t", "<f4", 4);
    Array aorg = load_npy(dir, "ao_origins", "<f4", 4), adir = load_npy(dir, "ao_directions", "<f4", 4);
    Array atmax = load_npy(dir, "ao_tmax", "<f4", 4), aocc = load_npy(dir, "ao_occluded", "|u1", 1);
    Array sdir = load_npy(dir, "sd_directions", "<f4", 4), siv = load_npy(dir, "sd_interval", "<f4", 4);
    Array scos = load_npy(dir, "sd_cos", "<f4", 4), sdepth = load_npy(dir, "sd_depth", "<f4", 4);
    Array scount = load_npy(dir, "sd_count", "<u4", 4);
    Array vdir = load_npy(dir, "svao_directions", "<f4", 4), viv = load_npy(dir, "svao_interval", "<f4", 4);
    Array vstate = load_npy(dir, "svao_state", "<f4", 4), vres = load_npy(dir, "svao_result", "<f4", 4);
    w.n[PRIMARY] = pdir.rows, w.n[AO] = aorg.rows, w.n[SD] = sdir.rows, w.n[SVAO] = vdir.rows;
    w.primary_dir = pdir.data, w.ao_org = aorg.data, w.ao_dir = adir.data, w.ao_tmax = atmax.data;
    w.sd_dir = sdir.data, w.sd_interval = siv.data, w.sd_cos = scos.data;
    w.sv_dir = vdir.data, w.sv_interval = viv.data, w.sv_state = vstate.data;
    w.primary_hit = calloc(w.n[PRIMARY] + 1, 4), w.primary_t = calloc(w.n[PRIMARY] + 1, 4);
    w.ao_occluded = calloc(w.n[AO] + 1, 1);
    w.sd_out = calloc(w.n[SD] + 1, sizeof(SdPayload)), w.sv_out = calloc(w.n[SVAO] + 1, sizeof(SampleState));

    /* One triangle mesh, twice: plain, and with the any-hit filter (a filter on the geometry
     * would run for the primary rays too). */
    RTCDevice device = rtcNewDevice(NULL);
    if (!device) die("rtcNewDevice failed", NULL);
    size_t ntris = tris.rows;
    double build_ms = 0.0;
    for (int s = 0; s < 2; s++) {
        RTCScene scene = rtcNewScene(device);
        RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        float *v = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 3 * ntris);
        unsigned *ix = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), ntris);
        if (!v || !ix) die("rtcSetNewGeometryBuffer failed", NULL);
        memcpy(v, tris.data, 9 * sizeof(float) * ntris);
        for (size_t i = 0; i < 3 * ntris; i++) ix[i] = (unsigned)i;
        if (s == 1) rtcSetGeometryIntersectFilterFunction(g, any_hit_filter);
        rtcCommitGeometry(g);
        rtcAttachGeometry(scene, g);
        rtcReleaseGeometry(g);
        double t0 = now(CLOCK_MONOTONIC);
        rtcCommitScene(scene);
        if (s == 0) build_ms = 1e3 * (now(CLOCK_MONOTONIC) - t0), w.plain = scene;
        else w.filtered = scene;
    }
    if (rtcGetDeviceError(device) != 0) die("Embree reported an error while building", NULL);

    Pool pool = {.w = &w, .threads = threads};
    pthread_barrier_init(&pool.start, NULL, (unsigned)threads + 1);
    pthread_barrier_init(&pool.done, NULL, (unsigned)threads + 1);
    pthread_t tid[64];
    if (threads > 64) die("at most 64 threads", NULL);
    for (int t = 0; t < threads; t++) pthread_create(&tid[t], NULL, worker, &pool);
    double wall[KINDS][64], cpu[KINDS][64];
    /* Alternate the kinds per repeat (a warm-up run of each first, untimed). */
    for (int r = -1; r < repeat; r++)
        for (int k = 0; k < KINDS; k++) {
            pool.kind = k;
            atomic_store(&pool.next, 0);
            /* The clocks start before the workers are released: taken after, a descheduled
             * main thread could start them late (seen: a 36 µs "run" of 30,307 rays). */
            double c0 = now(CLOCK_PROCESS_CPUTIME_ID), t0 = now(CLOCK_MONOTONIC);
            pthread_barrier_wait(&pool.start);
            pthread_barrier_wait(&pool.done);
            double t1 = now(CLOCK_MONOTONIC), c1 = now(CLOCK_PROCESS_CPUTIME_ID);
            if (r >= 0) wall[k][r] = t1 - t0, cpu[k][r] = c1 - c0;
        }
    pool.quit = 1;
    pthread_barrier_wait(&pool.start);
    for (int t = 0; t < threads; t++) pthread_join(tid[t], NULL);
    if (rtcGetDeviceError(device) != 0) die("Embree reported an error while tracing", NULL);

    /* Same answers? Primary: hit vs miss, another triangle. AO: occluded or not. */
    const int32_t *ours_hit = phit.data;
    const float *ours_t = pt.data;
    size_t hit_disagree = 0, other_triangle = 0, hits = 0, t_far = 0;
    for (size_t i = 0; i < w.n[PRIMARY]; i++) {
        hits += w.primary_hit[i] >= 0;
        if ((ours_hit[i] >= 0) != (w.primary_hit[i] >= 0)) hit_disagree++;
        else if (ours_hit[i] >= 0 && ours_hit[i] != w.primary_hit[i]) other_triangle++;
        else if (ours_hit[i] >= 0 && fabsf(ours_t[i] - w.primary_t[i]) > 1e-5f * ours_t[i]) t_far++;
    }
    const uint8_t *ours_occ = aocc.data;
    size_t occluded = 0, ao_disagree = 0;
    for (size_t i = 0; i < w.n[AO]; i++) occluded += w.ao_occluded[i], ao_disagree += w.ao_occluded[i] != ours_occ[i];
    /* SD: the reservoir's content depends on the order candidates arrive in (slot = ⌊u·count⌋
     * past N, the z-cull, tMax shrinking once count ≥ MAX_COUNT), which differs between any two
     * traversals; so compare in aggregate, and ray by ray what no order changes: a ray meeting
     * fewer than MAX_COUNT candidates never accepts one, so its count is the number of
     * surfaces on its interval, and its filled slots min(count, N). */
    const float *our_depth = sdepth.data;
    const uint32_t *our_count = scount.data;
    double sum_count[2] = {0, 0}, sum_filled[2] = {0, 0}, sum_depth[2] = {0, 0}, n_depth[2] = {0, 0};
    size_t below = 0, below_count_differ = 0, below_filled_differ = 0, saturated[2] = {0, 0};
    for (size_t i = 0; i < w.n[SD]; i++) {
        const float *d[2] = {our_depth + (size_t)layers * i, w.sd_out[i].depth};
        uint32_t c[2] = {our_count[i], w.sd_out[i].count};
        for (int s = 0; s < 2; s++) {
            sum_count[s] += c[s];
            sum_filled[s] += filled(d[s], layers);
            saturated[s] += c[s] >= w.sd_proto.max_count;
            for (int l = 0; l < layers; l++)
                if (d[s][l] < 1.0f) sum_depth[s] += d[s][l], n_depth[s] += 1;
        }
        if (c[0] < w.sd_proto.max_count && c[1] < w.sd_proto.max_count) {
            below++;
            below_count_differ += c[0] != c[1];
            below_filled_differ += filled(d[0], layers) != filled(d[1], layers);
        }
    }
    /* Ray-SVAO: no order changes the result. Whether the search ended (a hit on
     * [t_const, t_sphere]: every such hit ends it, and none is ever culled, since tMax only
     * shrinks to hits beyond t_sphere) is order-free; without it, t_halo is the largest hit on
     * [t_halo, t_const) and t_inside the nearest beyond t_sphere, both order-free. */
    const float *our_state = vres.data;
    size_t ended[2] = {0, 0}, inside[2] = {0, 0}, ended_differ = 0, state_differ = 0;
    for (size_t i = 0; i < w.n[SVAO]; i++) {
        const float *a = our_state + 4 * i, *b = &w.sv_out[i].t_halo, *s0 = w.sv_state + 4 * i;
        int e[2] = {a[0] >= a[2] && a[2] >= 0.0f, b[0] >= b[2] && b[2] >= 0.0f};
        ended[0] += e[0], ended[1] += e[1];
        if (e[0] != e[1]) ended_differ++;
        /* Inside hits of ended rays depend on the order (the ending hit culls farther ones). */
        if (!e[0]) inside[0] += a[1] < s0[1];
        if (!e[1]) inside[1] += b[1] < s0[1];
        else if (!e[0] && (fabsf(a[0] - b[0]) > 1e-5f * fabsf(a[0]) || fabsf(a[1] - b[1]) > 1e-5f * fabsf(a[1]))) state_differ++;
    }

    FILE *out = json_path ? fopen(json_path, "w") : stdout;
    if (!out) die("cannot write", json_path);
    fprintf(out, "{\"embree\": \"Embree 4.4 (libembree4 of the embreex wheel) from C, %d pthreads, rtcIntersect1 / rtcOccluded1, "
                 "intersection filter for the any-hit rays, default build\", \"threads\": %d, \"build_ms\": %.1f, \"triangles\": %zu,\n",
            threads, threads, build_ms, ntris);
    for (int k = 0; k < KINDS; k++) {
        stats_json(out, kind_name[k], w.n[k], wall[k], cpu[k], repeat);
        if (k == PRIMARY)
            fprintf(out, ", \"hit_fraction\": %.6f, \"hit_disagree\": %zu, \"other_triangle\": %zu, \"t_differ\": %zu", w.n[k] ? (double)hits / w.n[k] : 0.0, hit_disagree, other_triangle, t_far);
        if (k == AO)
            fprintf(out, ", \"occluded_fraction\": %.6f, \"disagree\": %zu", w.n[k] ? (double)occluded / w.n[k] : 0.0, ao_disagree);
        if (k == SD) {
            double n = w.n[k] ? (double)w.n[k] : 1.0;
            fprintf(out, ", \"mean_count\": [%.4f, %.4f], \"mean_filled\": [%.4f, %.4f], \"mean_depth\": [%.6f, %.6f], "
                         "\"saturated\": [%zu, %zu], \"below_max_count\": %zu, \"below_count_differ\": %zu, \"below_filled_differ\": %zu",
                    sum_count[0] / n, sum_count[1] / n, sum_filled[0] / n, sum_filled[1] / n,
                    n_depth[0] ? sum_depth[0] / n_depth[0] : 0.0, n_depth[1] ? sum_depth[1] / n_depth[1] : 0.0,
                    saturated[0], saturated[1], below, below_count_differ, below_filled_differ);
        }
        if (k == SVAO)
            fprintf(out, ", \"ended\": [%zu, %zu], \"inside_hit\": [%zu, %zu], \"ended_differ\": %zu, \"state_differ\": %zu",
                    ended[0], ended[1], inside[0], inside[1], ended_differ, state_differ);
        fprintf(out, "}%s\n", k + 1 < KINDS ? "," : "}");
    }
    if (json_path) fclose(out);
    rtcReleaseScene(w.plain);
    rtcReleaseScene(w.filtered);
    rtcReleaseDevice(device);
    return 0;
}

#else
int main(int argc, char **argv) {
    if (argc == 4 && strcmp(argv[1], "--replay") == 0) return replay(argv[2], argv[3]);
    die("built without Embree (AOKIT_NO_EMBREE): only --replay IN OUT", NULL);
    return 1;
}
#endif
