/* embree_paths.c: a minimal path tracer on Embree, the other side of make
 * bench's paths-per-second ratio (Debian packages no Embree tutorial). It
 * does what eclat's path integrator does on the bench scene, with no
 * materials: a diffuse surface of albedo 0.73 everywhere but the lamp, a
 * shadow ray toward a point of the lamp at every bounce (next-event
 * estimation), a cosine-distributed bounce, Russian roulette from the third
 * bounce, at most depth bounces. Its radiance is summed only so that no
 * compiler drops the work. */
#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdint.h>

#include "embree_bench.h"

#define ALBEDO 0.73f
#define RR_DEPTH 3

typedef struct {
	RTCScene sc;
	const bench_soup *s;
	int w, h, spp, depth;
	int lamps[64], n_lamps;
	atomic_int next_row, slot;
	double sum[16];   /* one a thread */
} job;

static float next(uint64_t *st)   /* xorshift64*, in [0, 1) */
{
	*st ^= *st >> 12;
	*st ^= *st << 25;
	*st ^= *st >> 27;
	return (float)((*st * 0x2545f4914f6cdd1dull) >> 40) * (1.0f / 16777216.0f);
}

static float path(job *j, struct RTCIntersectContext *ctx, uint64_t *st, float o[3], float d[3])
{
	float radiance = 0, weight = 1;
	for (int depth = 0; depth <= j->depth; depth++) {
		struct RTCRayHit rh = { .ray = { o[0], o[1], o[2], 0, d[0], d[1], d[2], 0, INFINITY, -1u, 0, 0 },
		                 .hit = { .geomID = RTC_INVALID_GEOMETRY_ID } };
		rtcIntersect1(j->sc, ctx, &rh);
		if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID)
			break;
		if (j->s->emits[rh.hit.primID]) {
			if (depth == 0)
				radiance += 12 * weight;
			break;
		}
		float n[3] = { rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z }, len = sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
		float facing = n[0] * d[0] + n[1] * d[1] + n[2] * d[2] > 0 ? -1.0f : 1.0f;
		for (int a = 0; a < 3; a++) {
			n[a] *= facing / len;
			o[a] += rh.ray.tfar * d[a] + 1e-4f * n[a];
		}
		weight *= ALBEDO;
		if (j->n_lamps) {   /* next-event estimation */
			const float (*l)[3] = j->s->v[j->lamps[(int)(next(st) * j->n_lamps) % j->n_lamps]];
			float u = next(st), v = next(st), to[3];
			if (u + v > 1)
				u = 1 - u, v = 1 - v;
			for (int a = 0; a < 3; a++)
				to[a] = l[0][a] + u * (l[1][a] - l[0][a]) + v * (l[2][a] - l[0][a]) - o[a];
			struct RTCRay shadow = { o[0], o[1], o[2], 0, to[0], to[1], to[2], 0, 0.999f, -1u, 0, 0 };
			rtcOccluded1(j->sc, ctx, &shadow);
			float cosine = n[0] * to[0] + n[1] * to[1] + n[2] * to[2];
			if (shadow.tfar >= 0 && cosine > 0)
				radiance += weight * cosine / (to[0] * to[0] + to[1] * to[1] + to[2] * to[2]);
		}
		float z = 2 * next(st) - 1, phi = 6.2831853f * next(st), r = sqrtf(1 - z * z);
		d[0] = n[0] + r * cosf(phi), d[1] = n[1] + r * sinf(phi), d[2] = n[2] + z;
		if (depth + 1 >= RR_DEPTH) {
			if (next(st) >= ALBEDO)
				break;
			weight /= ALBEDO;
		}
	}
	return radiance;
}

static void *worker(void *arg)
{
	job *j = arg;
	struct RTCIntersectContext ctx;
	rtcInitIntersectContext(&ctx);
	double sum = 0;
	const float (*cam)[3] = j->s->camera;
	for (;;) {
		int y = atomic_fetch_add(&j->next_row, 1);
		if (y >= j->h)
			break;
		for (int x = 0; x < j->w; x++) {
			uint64_t st = 0x9e3779b97f4a7c15ull ^ ((uint64_t)y << 32 | (uint64_t)x) * 0xbf58476d1ce4e5b9ull;
			for (int k = 0; k < j->spp; k++) {
				float sx = (x + next(&st)) / j->w - 0.5f, sy = 0.5f - (y + next(&st)) / j->h, o[3], d[3];
				for (int a = 0; a < 3; a++) {
					o[a] = cam[0][a];
					d[a] = cam[1][a] + sx * cam[2][a] + sy * cam[3][a];
				}
				sum += path(j, &ctx, &st, o, d);
			}
		}
	}
	j->sum[atomic_fetch_add(&j->slot, 1)] = sum;
	return NULL;
}

double bench_embree_paths(RTCScene sc, const bench_soup *s, int w, int h, int spp, int depth, int threads)
{
	job j = { .sc = sc, .s = s, .w = w, .h = h, .spp = spp, .depth = depth };
	for (int i = 0; i < s->n && j.n_lamps < 64; i++)
		if (s->emits[i])
			j.lamps[j.n_lamps++] = i;
	pthread_t th[16];
	threads = threads > 16 ? 16 : threads;
	double t0 = bench_now_ms();
	for (int i = 0; i < threads; i++)
		pthread_create(&th[i], NULL, worker, &j);
	for (int i = 0; i < threads; i++)
		pthread_join(th[i], NULL);
	return (double)w * h * spp / ((bench_now_ms() - t0) * 1e3);
}
