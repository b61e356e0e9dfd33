/* embree_bench.h: what make bench's comparison with Embree shares
 * (tests/bench/embree_bench.c, embree_paths.c): the scene flattened into one
 * world-space triangle soup, as Embree and the minimal path tracer see it. */
#ifndef ECLAT_EMBREE_BENCH_H
#define ECLAT_EMBREE_BENCH_H

#include <embree3/rtcore.h>

typedef struct {
	float (*v)[3][3];   /* the corners of each triangle, in world space */
	int n;
	int *emits;         /* 1 where the triangle is an emitter (the lamp) */
	float camera[4][3]; /* location, direction, right, up (dev_params) */
} bench_soup;

/* Embree's scene over the soup, committed; *ms gets the build time. */
RTCScene bench_embree_scene(RTCDevice dev, const bench_soup *s, double *ms);

/* Milliseconds on the monotonic clock. */
double bench_now_ms(void);

/* The minimal path tracer (embree_paths.c): w x h pixels, spp samples,
 * at most depth bounces, on threads threads; returns paths per second. */
double bench_embree_paths(RTCScene sc, const bench_soup *s, int w, int h, int spp, int depth, int threads);

#endif
