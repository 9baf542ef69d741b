/*
 * Embree reference for the mesh BVH benchmark `benches/bvh.rs`.
 *
 * Builds exactly the same height-field meshes (10k, 100k, 1M triangles) and the same three
 * ray sets as bvh.rs, then measures with Embree, on one thread:
 *   build   - scene creation, vertex/index upload (double -> float) and rtcCommitScene
 *   camera  - rtcIntersect1 (closest hit) for the coherent camera rays
 *   random  - rtcIntersect1 for the incoherent random rays (same xorshift, same seed)
 *   shadow  - rtcOccluded1 from the camera rays' nearest hits towards the light,
 *             tnear 1e-6, tfar 1.0, direction light - p (not normalised)
 * for the build qualities LOW, MEDIUM (Embree's default) and HIGH.
 *
 * Every ray is generated in double with the same formulas and in the same order as bvh.rs,
 * then rounded to float for Embree. Each ray loop is calibrated to last about 0.1 s, then
 * repeated 5 times; rays_per_s is the best repetition, median_rays_per_s the median one.
 * Checksums (hits and the sum of hit t; occluded count) let the work be checked against
 * trace's own answers.
 *
 * mem_bytes is Embree's own count (memory monitor callback) of the bytes a build allocated:
 * the BVH plus Embree's float vertex and index buffers (12 bytes per vertex and per triangle).
 *
 * Output, one line per measurement:
 *   embree info version=... ...
 *   embree size=N triangles=T quality=Q kind=build best_s=... median_s=... mem_bytes=...
 *   embree size=N triangles=T quality=Q kind=camera rays=R rays_per_s=... median_rays_per_s=... hits=H tsum=S
 *   embree size=N triangles=T quality=Q kind=shadow rays=R rays_per_s=... median_rays_per_s=... occluded=O
 *
 * Usage: embree_bench [size ...]          (default: 10000 100000 1000000)
 * Env:   EMBREE_THREADS=n  build threads (default 1; 0 = all cores)
 *        EMBREE_CONFIG=... extra device configuration, e.g. "verbose=1" (prints the ISA)
 *
 * Build: scripts/embree.sh does it (gcc -O2 -march=native ... -lembree3 or -lembree4 -lm).
 */

#define _POSIX_C_SOURCE 200809L

/* Embree 4 if installed, else Embree 3. EMBREE_MAJOR may also be given with -D. */
#if !defined(EMBREE_MAJOR)
#if defined(__has_include)
#if __has_include(<embree4/rtcore.h>)
#define EMBREE_MAJOR 4
#else
#define EMBREE_MAJOR 3
#endif
#else
#define EMBREE_MAJOR 3
#endif
#endif

#if EMBREE_MAJOR == 4
#include <embree4/rtcore.h>
#else
#include <embree3/rtcore.h>
#endif

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <time.h>
#include <xmmintrin.h>
#include <pmmintrin.h>

#define RAYS 20000
#define REPETITIONS 5
#define TARGET_REP_SECONDS 0.1

/* ---------------------------------------------------------------------------------------- */
/* Small helpers                                                                             */

static double now_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void *checked_malloc(size_t bytes)
{
    void *p = malloc(bytes);
    if (!p) {
        fprintf(stderr, "embree_bench: out of memory (%zu bytes)\n", bytes);
        exit(1);
    }
    return p;
}

static int compare_doubles(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Median of n values (sorts them in place). */
static double median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, compare_doubles);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

typedef struct {
    double x, y, z;
} Vec3;

static Vec3 vec3(double x, double y, double z)
{
    Vec3 v = {x, y, z};
    return v;
}

/* A ray in double, as bvh.rs builds it: origin + t * direction, t in (tmin, tmax). */
typedef struct {
    Vec3 origin, direction;
    double tmin, tmax;
} Ray;

static Ray ray_new(Vec3 origin, Vec3 direction)
{
    Ray r = {origin, direction, 0.0, INFINITY};
    return r;
}

/* ---------------------------------------------------------------------------------------- */
/* The scene and the rays of bvh.rs                                                          */

/* The height field of about `triangles` triangles over [-10, 10]^2 (bvh.rs `terrain`):
 * side x side vertices, two triangles per grid cell with the same winding. */
typedef struct {
    size_t side;
    size_t vertex_count, triangle_count;
    Vec3 *vertices;
    uint32_t *indices; /* 3 per triangle */
} Terrain;

static Terrain terrain(size_t triangles)
{
    Terrain t;
    /* Rust's f64::round rounds halves away from zero, as C's round() does. */
    size_t side = (size_t)round(sqrt((double)triangles / 2.0)) + 1;
    if (side < 2)
        side = 2;
    t.side = side;
    t.vertex_count = side * side;
    t.triangle_count = 2 * (side - 1) * (side - 1);
    t.vertices = checked_malloc(t.vertex_count * sizeof *t.vertices);
    t.indices = checked_malloc(3 * t.triangle_count * sizeof *t.indices);
    for (size_t j = 0; j < side; j++) {
        for (size_t i = 0; i < side; i++) {
            double x = 20.0 * ((double)i / (double)(side - 1) - 0.5);
            double z = 20.0 * ((double)j / (double)(side - 1) - 0.5);
            double y = 0.8 * sin(0.9 * x) * cos(0.7 * z) + 0.3 * sin(2.3 * x + 1.7 * z);
            t.vertices[j * side + i] = vec3(x, y, z);
        }
    }
    uint32_t *f = t.indices;
    uint32_t s = (uint32_t)side;
    for (size_t j = 0; j + 1 < side; j++) {
        for (size_t i = 0; i + 1 < side; i++) {
            uint32_t a = (uint32_t)(j * side + i);
            *f++ = a;         *f++ = a + s; *f++ = a + 1;
            *f++ = a + 1;     *f++ = a + s; *f++ = a + s + 1;
        }
    }
    return t;
}

/* bvh.rs's xorshift generator: 53 random bits as a double in [0, 1). */
static double rng_next(uint64_t *state)
{
    *state ^= *state << 13;
    *state ^= *state >> 7;
    *state ^= *state << 17;
    return (double)(*state >> 11) / (double)(UINT64_C(1) << 53);
}

/* Camera rays from above the terrain through a 141 x 141 grid (bvh.rs `camera_rays`). */
static Ray *camera_rays(size_t *count)
{
    size_t side = (size_t)sqrt((double)RAYS); /* truncation, like `as usize` */
    Vec3 eye = vec3(0.0, 12.0, -18.0);
    Ray *rays = checked_malloc(side * side * sizeof *rays);
    size_t n = 0;
    for (size_t j = 0; j < side; j++) {
        for (size_t i = 0; i < side; i++) {
            Vec3 target = vec3(20.0 * ((double)i / (double)side - 0.5), 0.0,
                               20.0 * ((double)j / (double)side - 0.5));
            rays[n++] = ray_new(eye, vec3(target.x - eye.x, target.y - eye.y, target.z - eye.z));
        }
    }
    *count = n;
    return rays;
}

/* Random origins above the terrain, random downward-ish directions (bvh.rs `random_rays`).
 * The generator is drawn in the same order as the Rust argument evaluation (left to right). */
static Ray *random_rays(size_t *count)
{
    uint64_t state = UINT64_C(0x9E3779B97F4A7C15);
    Ray *rays = checked_malloc(RAYS * sizeof *rays);
    for (size_t k = 0; k < RAYS; k++) {
        double ox = 20.0 * rng_next(&state) - 10.0;
        double oy = 3.0 * rng_next(&state) + 1.5;
        double oz = 20.0 * rng_next(&state) - 10.0;
        double dx = 2.0 * rng_next(&state) - 1.0;
        double dy = -rng_next(&state) - 0.05;
        double dz = 2.0 * rng_next(&state) - 1.0;
        rays[k] = ray_new(vec3(ox, oy, oz), vec3(dx, dy, dz));
    }
    *count = RAYS;
    return rays;
}

/* ---------------------------------------------------------------------------------------- */
/* Embree                                                                                    */

/* Bytes Embree currently has allocated, from its memory monitor callback. */
static long long embree_bytes = 0;

static bool memory_monitor(void *user, ssize_t bytes, bool post)
{
    (void)user;
    (void)post;
    embree_bytes += (long long)bytes;
    return true;
}

static void error_handler(void *user, enum RTCError code, const char *message)
{
    (void)user;
    fprintf(stderr, "embree_bench: Embree error %d: %s\n", (int)code, message ? message : "");
    exit(1);
}

/* Embree 3 and 4 differ in the trailing argument of the ray queries. */
static inline void intersect1(RTCScene scene, struct RTCRayHit *rh)
{
#if EMBREE_MAJOR == 4
    rtcIntersect1(scene, rh, NULL);
#else
    struct RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    rtcIntersect1(scene, &context, rh);
#endif
}

static inline void occluded1(RTCScene scene, struct RTCRay *ray)
{
#if EMBREE_MAJOR == 4
    rtcOccluded1(scene, ray, NULL);
#else
    struct RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    rtcOccluded1(scene, &context, ray);
#endif
}

/* The Embree ray for a double ray (rounded to float). */
static struct RTCRay embree_ray(const Ray *r)
{
    struct RTCRay e;
    e.org_x = (float)r->origin.x;
    e.org_y = (float)r->origin.y;
    e.org_z = (float)r->origin.z;
    e.tnear = (float)r->tmin;
    e.dir_x = (float)r->direction.x;
    e.dir_y = (float)r->direction.y;
    e.dir_z = (float)r->direction.z;
    e.time = 0.0f;
    e.tfar = (float)r->tmax;
    e.mask = 0xFFFFFFFFu;
    e.id = 0;
    e.flags = 0;
    return e;
}

/* An RTCRayHit ready for rtcIntersect1 (no hit yet). */
static struct RTCRayHit embree_rayhit(const struct RTCRay *ray)
{
    struct RTCRayHit rh;
    memset(&rh, 0, sizeof rh);
    rh.ray = *ray;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    return rh;
}

/* Builds the scene for the terrain with the given quality. */
static RTCScene build_scene(RTCDevice device, const Terrain *t, enum RTCBuildQuality quality)
{
    RTCScene scene = rtcNewScene(device);
    rtcSetSceneBuildQuality(scene, quality);
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetGeometryBuildQuality(geometry, quality);
    /* Embree owns these buffers (it pads the vertex buffer for its 16-byte loads). */
    float *v = rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                       3 * sizeof(float), t->vertex_count);
    for (size_t k = 0; k < t->vertex_count; k++) {
        v[3 * k + 0] = (float)t->vertices[k].x;
        v[3 * k + 1] = (float)t->vertices[k].y;
        v[3 * k + 2] = (float)t->vertices[k].z;
    }
    uint32_t *f = rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                          3 * sizeof(uint32_t), t->triangle_count);
    memcpy(f, t->indices, 3 * t->triangle_count * sizeof *f);
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(scene, geometry);
    rtcReleaseGeometry(geometry);
    rtcCommitScene(scene);
    return scene;
}

/* ---------------------------------------------------------------------------------------- */
/* Timed loops                                                                               */

typedef struct {
    long long hits; /* rays that hit (or were occluded) */
    double tsum;    /* sum of the hit distances (closest-hit loops only) */
} Checksum;

/* One pass of closest-hit queries over all rays. */
static Checksum intersect_pass(RTCScene scene, const struct RTCRay *rays, size_t n)
{
    Checksum c = {0, 0.0};
    for (size_t k = 0; k < n; k++) {
        struct RTCRayHit rh = embree_rayhit(&rays[k]);
        intersect1(scene, &rh);
        if (rh.hit.geomID != RTC_INVALID_GEOMETRY_ID) {
            c.hits++;
            c.tsum += rh.ray.tfar;
        }
    }
    return c;
}

/* One pass of any-hit queries over all rays (Embree sets tfar to -inf when occluded). */
static Checksum occluded_pass(RTCScene scene, const struct RTCRay *rays, size_t n)
{
    Checksum c = {0, 0.0};
    for (size_t k = 0; k < n; k++) {
        struct RTCRay r = rays[k];
        occluded1(scene, &r);
        if (r.tfar < 0.0f)
            c.hits++;
    }
    return c;
}

typedef Checksum (*Pass)(RTCScene, const struct RTCRay *, size_t);

/* Embree recommends flush-to-zero and denormals-are-zero while it runs. They are switched
 * on only around the timed Embree work (builds and ray loops), so that the double-precision
 * mesh and ray generation run in the default mode, as in bvh.rs. */
static unsigned int fp_embree_mode(void)
{
    unsigned int saved = _mm_getcsr();
    _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
    _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
    return saved;
}

static void fp_restore(unsigned int saved)
{
    _mm_setcsr(saved);
}

/* Times `pass`: calibrates the passes per repetition to about TARGET_REP_SECONDS, then keeps
 * the best and median of REPETITIONS repetitions (in rays per second). */
static void time_rays(Pass pass, RTCScene scene, const struct RTCRay *rays, size_t n,
                      double *best, double *med, Checksum *check)
{
    unsigned int fp = fp_embree_mode();
    double t0 = now_seconds();
    *check = pass(scene, rays, n); /* warm-up, and the checksum */
    double once = now_seconds() - t0;
    long passes = (long)ceil(TARGET_REP_SECONDS / (once > 1e-9 ? once : 1e-9));
    if (passes < 1)
        passes = 1;
    double rates[REPETITIONS];
    volatile long long sink = 0;
    for (int r = 0; r < REPETITIONS; r++) {
        double start = now_seconds();
        for (long p = 0; p < passes; p++)
            sink += pass(scene, rays, n).hits;
        double elapsed = now_seconds() - start;
        rates[r] = (double)passes * (double)n / elapsed;
    }
    (void)sink;
    fp_restore(fp);
    *best = rates[0];
    for (int r = 1; r < REPETITIONS; r++)
        if (rates[r] > *best)
            *best = rates[r];
    *med = median(rates, REPETITIONS);
}

/* ---------------------------------------------------------------------------------------- */

static const char *quality_name(enum RTCBuildQuality q)
{
    switch (q) {
    case RTC_BUILD_QUALITY_LOW: return "low";
    case RTC_BUILD_QUALITY_MEDIUM: return "medium";
    case RTC_BUILD_QUALITY_HIGH: return "high";
    default: return "other";
    }
}

static void run_size(RTCDevice device, size_t size)
{
    Terrain t = terrain(size);
    size_t camera_count, random_count;
    Ray *camera = camera_rays(&camera_count);
    Ray *random = random_rays(&random_count);
    struct RTCRay *camera_e = checked_malloc(camera_count * sizeof *camera_e);
    struct RTCRay *random_e = checked_malloc(random_count * sizeof *random_e);
    struct RTCRay *shadow_e = checked_malloc(camera_count * sizeof *shadow_e);
    for (size_t k = 0; k < camera_count; k++)
        camera_e[k] = embree_ray(&camera[k]);
    for (size_t k = 0; k < random_count; k++)
        random_e[k] = embree_ray(&random[k]);

    const enum RTCBuildQuality qualities[] = {RTC_BUILD_QUALITY_LOW, RTC_BUILD_QUALITY_MEDIUM,
                                              RTC_BUILD_QUALITY_HIGH};
    for (size_t qi = 0; qi < sizeof qualities / sizeof qualities[0]; qi++) {
        enum RTCBuildQuality quality = qualities[qi];
        const char *qname = quality_name(quality);

        /* Build: 5 samples, as bvh.rs's build bench; keep the last scene for the rays. */
        double build_times[REPETITIONS];
        RTCScene scene = NULL;
        long long mem = 0;
        for (int r = 0; r < REPETITIONS; r++) {
            if (scene)
                rtcReleaseScene(scene);
            scene = NULL;
            long long before = embree_bytes;
            unsigned int fp = fp_embree_mode();
            double start = now_seconds();
            scene = build_scene(device, &t, quality);
            build_times[r] = now_seconds() - start;
            fp_restore(fp);
            mem = embree_bytes - before;
        }
        double build_best = build_times[0];
        for (int r = 1; r < REPETITIONS; r++)
            if (build_times[r] < build_best)
                build_best = build_times[r];
        printf("embree size=%zu triangles=%zu quality=%s kind=build best_s=%.6f median_s=%.6f "
               "mem_bytes=%lld\n",
               size, t.triangle_count, qname, build_best, median(build_times, REPETITIONS), mem);
        fflush(stdout);

        double best, med;
        Checksum c;

        time_rays(intersect_pass, scene, camera_e, camera_count, &best, &med, &c);
        printf("embree size=%zu triangles=%zu quality=%s kind=camera rays=%zu rays_per_s=%.0f "
               "median_rays_per_s=%.0f hits=%lld tsum=%.6f\n",
               size, t.triangle_count, qname, camera_count, best, med, c.hits, c.tsum);
        fflush(stdout);

        time_rays(intersect_pass, scene, random_e, random_count, &best, &med, &c);
        printf("embree size=%zu triangles=%zu quality=%s kind=random rays=%zu rays_per_s=%.0f "
               "median_rays_per_s=%.0f hits=%lld tsum=%.6f\n",
               size, t.triangle_count, qname, random_count, best, med, c.hits, c.tsum);
        fflush(stdout);

        /* Shadow rays, as bvh.rs: from each camera ray's nearest hit (found by Embree with
         * this scene), p = origin + t * dir in double, towards the light, over (1e-6, 1). */
        const Vec3 light = vec3(-20.0, 30.0, -10.0);
        size_t shadow_count = 0;
        for (size_t k = 0; k < camera_count; k++) {
            struct RTCRayHit rh = embree_rayhit(&camera_e[k]);
            intersect1(scene, &rh);
            if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID)
                continue;
            double th = rh.ray.tfar;
            const Ray *r = &camera[k];
            Vec3 p = vec3(r->origin.x + th * r->direction.x, r->origin.y + th * r->direction.y,
                          r->origin.z + th * r->direction.z);
            Ray s = ray_new(p, vec3(light.x - p.x, light.y - p.y, light.z - p.z));
            s.tmin = 1e-6;
            s.tmax = 1.0;
            shadow_e[shadow_count++] = embree_ray(&s);
        }
        time_rays(occluded_pass, scene, shadow_e, shadow_count, &best, &med, &c);
        printf("embree size=%zu triangles=%zu quality=%s kind=shadow rays=%zu rays_per_s=%.0f "
               "median_rays_per_s=%.0f occluded=%lld\n",
               size, t.triangle_count, qname, shadow_count, best, med, c.hits);
        fflush(stdout);

        rtcReleaseScene(scene);
    }

    free(camera_e);
    free(random_e);
    free(shadow_e);
    free(camera);
    free(random);
    free(t.vertices);
    free(t.indices);
}

int main(int argc, char **argv)
{
    const char *threads_env = getenv("EMBREE_THREADS");
    int threads = threads_env ? atoi(threads_env) : 1;
    const char *extra = getenv("EMBREE_CONFIG");
    char config[512];
    snprintf(config, sizeof config, "threads=%d%s%s", threads, extra ? "," : "",
             extra ? extra : "");

    RTCDevice device = rtcNewDevice(config);
    if (!device) {
        fprintf(stderr, "embree_bench: rtcNewDevice(\"%s\") failed (error %d)\n", config,
                (int)rtcGetDeviceError(NULL));
        return 1;
    }
    rtcSetDeviceErrorFunction(device, error_handler, NULL);
    rtcSetDeviceMemoryMonitorFunction(device, memory_monitor, NULL);

    /* Facts about this Embree build that matter for the comparison. */
    static const char *tasking[] = {"internal", "tbb", "ppl"};
    ssize_t task = rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_TASKING_SYSTEM);
    printf("embree info version=%zd.%zd.%zd header=embree%d tasking=%s threads=%d "
           "backface_culling=%zd ignore_invalid_rays=%zd filter_functions=%zd "
           "native_ray8=%zd native_ray16=%zd\n",
           rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_VERSION_MAJOR),
           rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_VERSION_MINOR),
           rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_VERSION_PATCH), EMBREE_MAJOR,
           task >= 0 && task < 3 ? tasking[task] : "unknown", threads,
           rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_BACKFACE_CULLING_ENABLED),
           rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_IGNORE_INVALID_RAYS_ENABLED),
           rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_FILTER_FUNCTION_SUPPORTED),
           rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_NATIVE_RAY8_SUPPORTED),
           rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_NATIVE_RAY16_SUPPORTED));
    fflush(stdout);

    size_t default_sizes[] = {10000, 100000, 1000000};
    if (argc > 1) {
        for (int a = 1; a < argc; a++)
            run_size(device, (size_t)strtoull(argv[a], NULL, 10));
    } else {
        for (size_t k = 0; k < sizeof default_sizes / sizeof default_sizes[0]; k++)
            run_size(device, default_sizes[k]);
    }

    rtcReleaseDevice(device);
    return 0;
}
