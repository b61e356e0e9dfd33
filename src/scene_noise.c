/* scene_noise.c: POV-Ray's Noise and DTurbulence on the host, for the host's
 * run of the scene's functions (f_noise3d in scene_function_eval) and for
 * vturbulence(): kernels/pattern.cl's pattern_noise and pattern_dturbulence
 * step for step, in float as the device computes them, over the same tables
 * (kernels/pattern_tables.cl, included here as C). */
#include <math.h>

#include "scene.h"

typedef unsigned short ushort;
#define constant static const
#include "../kernels/pattern_tables.cl"
#undef constant

static float mixf(float a, float b, float t)   /* OpenCL's mix */
{
	return a + (b - a) * t;
}

static float clampf(float v, float lo, float hi)
{
	return v < lo ? lo : v > hi ? hi : v;
}

/* Clamped first: a coordinate past int (or NaN) would make the cast
 * undefined; the noise there is meaningless in float anyway. */
static int lattice(float floor_x)
{
	return ((int)fminf(fmaxf(floor_x, -1e9f), 1e9f) + 10000) & 0xfff;
}

static int corner(int hxy, int iz)
{
	return pattern_hash[(hxy ^ iz) & 0xfff] & 0xff;
}

static float incr(int k, float s, float x, float y, float z)
{
	return s * (0.5f * pattern_rtable[k] + pattern_rtable[k + 1] * x + pattern_rtable[k + 2] * y +
	            pattern_rtable[k + 3] * z);
}

static float grad_at(int b, float rx, float ry, float rz)
{
	const float *g = &pattern_grad[3 * (b & 2047)];
	return g[0] * rx + g[1] * ry + g[2] * rz;
}

/* noise_generator 3: Perlin's gradient noise (pattern_solid_noise). */
static float solid_noise(const float p[3])
{
	const float roll = 0.023157213f;
	float t[3], f[3], r0[3], r1[3], s[3];
	int b0[3], b1[3];
	for (int k = 0; k < 3; k++) {
		t[k] = p[k] + roll;
		f[k] = floorf(t[k]);
		r0[k] = t[k] - f[k];
		r1[k] = r0[k] - 1.0f;
		b0[k] = ((int)f[k] + 1664) & 2047;
		b1[k] = (b0[k] + 1) & 2047;
		s[k] = r0[k] * r0[k] * (3.0f - 2.0f * r0[k]);
	}
	int i = pattern_perm[b0[0]], j = pattern_perm[b1[0]];
	int b00 = pattern_perm[(i + b0[1]) & 2047], b10 = pattern_perm[(j + b0[1]) & 2047];
	int b01 = pattern_perm[(i + b1[1]) & 2047], b11 = pattern_perm[(j + b1[1]) & 2047];
	float a = mixf(grad_at(b00 + b0[2], r0[0], r0[1], r0[2]), grad_at(b10 + b0[2], r1[0], r0[1], r0[2]), s[0]);
	float b = mixf(grad_at(b01 + b0[2], r0[0], r1[1], r0[2]), grad_at(b11 + b0[2], r1[0], r1[1], r0[2]), s[0]);
	float c = mixf(a, b, s[1]);
	a = mixf(grad_at(b00 + b1[2], r0[0], r0[1], r1[2]), grad_at(b10 + b1[2], r1[0], r0[1], r1[2]), s[0]);
	b = mixf(grad_at(b01 + b1[2], r0[0], r1[1], r1[2]), grad_at(b11 + b1[2], r1[0], r1[1], r1[2]), s[0]);
	float d = mixf(a, b, s[1]);
	return mixf(c, d, s[2]);
}

/* The lattice cell of p that Noise and DNoise both start from
 * (pattern_corners): the offsets from its two corners, the smoothstep
 * weights, the hashes of its four columns and its z index. */
struct cell {
	float f0[3], f1[3], s[3], t[3];
	int h00, h10, h01, h11, iz;
};

static struct cell cell_of(const float p[3])
{
	struct cell c;
	int l[3];
	for (int k = 0; k < 3; k++) {
		float fl = floorf(p[k]);
		c.f0[k] = p[k] - fl;
		c.f1[k] = c.f0[k] - 1.0f;
		l[k] = lattice(fl);
		c.s[k] = c.f0[k] * c.f0[k] * (3.0f - 2.0f * c.f0[k]);
		c.t[k] = 1.0f - c.s[k];
	}
	int ix = l[0], iy = l[1];
	c.iz = l[2];
	c.h00 = pattern_hash[(pattern_hash[ix] ^ iy) & 0xfff];
	c.h10 = pattern_hash[(pattern_hash[(ix + 1) & 0xfff] ^ iy) & 0xfff];
	c.h01 = pattern_hash[(pattern_hash[ix] ^ (iy + 1)) & 0xfff];
	c.h11 = pattern_hash[(pattern_hash[(ix + 1) & 0xfff] ^ (iy + 1)) & 0xfff];
	return c;
}

float scene_noise(const float p[3], int generator)
{
	if (generator == 3)
		return clampf(0.5f * (1.59f * solid_noise(p) + 0.985f), 0.0f, 1.0f);
	struct cell c = cell_of(p);
	const float *f0 = c.f0, *f1 = c.f1, *s = c.s, *t = c.t;
	int iz = c.iz;
	float sum = incr(corner(c.h00, iz), t[0] * t[1] * t[2], f0[0], f0[1], f0[2]) +
	            incr(corner(c.h10, iz), s[0] * t[1] * t[2], f1[0], f0[1], f0[2]) +
	            incr(corner(c.h01, iz), t[0] * s[1] * t[2], f0[0], f1[1], f0[2]) +
	            incr(corner(c.h11, iz), s[0] * s[1] * t[2], f1[0], f1[1], f0[2]) +
	            incr(corner(c.h00, iz + 1), t[0] * t[1] * s[2], f0[0], f0[1], f1[2]) +
	            incr(corner(c.h10, iz + 1), s[0] * t[1] * s[2], f1[0], f0[1], f1[2]) +
	            incr(corner(c.h01, iz + 1), t[0] * s[1] * s[2], f0[0], f1[1], f1[2]) +
	            incr(corner(c.h11, iz + 1), s[0] * s[1] * s[2], f1[0], f1[1], f1[2]);
	if (generator == 2)
		sum = (sum + 1.05242f) * 0.48985582f;
	else
		sum += 0.5f;
	return clampf(sum, 0.0f, 1.0f);
}

/* One corner of POV-Ray's DNoise (pattern_dincr): entries k, k + 4, k + 8. */
static void dincr(int k, float s, float x, float y, float z, float out[3])
{
	out[0] += incr(k, s, x, y, z);
	out[1] += incr(k + 4, s, x, y, z);
	out[2] += incr(k + 8, s, x, y, z);
}

/* POV-Ray's DNoise (pattern_dnoise), its corners in the device's order. */
static void dnoise(const float p[3], float out[3])
{
	struct cell c = cell_of(p);
	const float *f0 = c.f0, *f1 = c.f1, *s = c.s, *t = c.t;
	int iz = c.iz;
	out[0] = out[1] = out[2] = 0.0f;
	dincr(corner(c.h00, iz), t[0] * t[1] * t[2], f0[0], f0[1], f0[2], out);
	dincr(corner(c.h10, iz), s[0] * t[1] * t[2], f1[0], f0[1], f0[2], out);
	dincr(corner(c.h11, iz), s[0] * s[1] * t[2], f1[0], f1[1], f0[2], out);
	dincr(corner(c.h01, iz), t[0] * s[1] * t[2], f0[0], f1[1], f0[2], out);
	dincr(corner(c.h01, iz + 1), t[0] * s[1] * s[2], f0[0], f1[1], f1[2], out);
	dincr(corner(c.h11, iz + 1), s[0] * s[1] * s[2], f1[0], f1[1], f1[2], out);
	dincr(corner(c.h10, iz + 1), s[0] * t[1] * s[2], f1[0], f0[1], f1[2], out);
	dincr(corner(c.h00, iz + 1), t[0] * t[1] * s[2], f0[0], f0[1], f1[2], out);
}

void scene_dturbulence(const float p[3], float omega, float lambda, int octaves, float out[3])
{
	dnoise(p, out);
	float l = lambda, o = omega;
	for (int i = 2; i <= octaves; i++) {
		float q[3] = { p[0] * l, p[1] * l, p[2] * l }, v[3];
		dnoise(q, v);
		for (int k = 0; k < 3; k++)
			out[k] += o * v[k];
		l *= lambda;
		o *= omega;
	}
}

/* The internal functions of functions.inc that sum octaves of Noise
 * (fnintern.cpp's f_noise_generator, f_hetero_mf, f_ridge, f_ridged_mf), step
 * for step as kernels/pattern.cl's function_noise4 ... function_ridged_mf: in
 * double, each octave's point made float for the noise as f_noise3d's is.
 *
 * POV-Ray takes a parameter as an int with a C cast, undefined past int and
 * for NaN, and loops as many octaves (or f_hetero_mf's exponent) as it says,
 * which a hostile 1e9 makes a hang. Here a generator past int or NaN is 0 (the
 * x86 cast's INT_MIN & 3: the original noise, as 1), and counts are clamped to
 * [-SCENE_OCTAVES_MAX, SCENE_OCTAVES_MAX]: past 64 octaves a lacunarity of 2
 * has made the point 2^64 times larger, where float noise is constant (no
 * fraction is left in the lattice coordinates), so the octaves a clamp drops
 * add nothing POV-Ray's values would show in a render. A NaN octave count
 * loops none, as POV-Ray does, and gives what POV-Ray gives: the first
 * octave (f_ridged_mf) or NaN (the others' fraction of an octave). */
#define SCENE_OCTAVES_MAX 64.0

static int noise_generator_of(double p)
{
	return p > -2147483648.0 && p < 2147483648.0 ? (int)p & 3 : 0;
}

static double clamp_count(double n)
{
	return isnan(n) ? n : fmin(fmax(n, -SCENE_OCTAVES_MAX), SCENE_OCTAVES_MAX);
}

static double noise_at(double x, double y, double z, int generator)
{
	float p[3] = { (float)x, (float)y, (float)z };
	return scene_noise(p, generator);
}

/* f_hetero_mf: x y z, H, lacunarity, octaves, offset, T (an exponent), generator. */
static double hetero_mf(const double *a)
{
	double x = a[0], y = a[1], z = a[2], h = a[3], lacunarity = a[4], octaves = clamp_count(a[5]);
	double offset = a[6], t = clamp_count(a[7]);
	int generator = noise_generator_of(a[8]);
	int power = t > 0 ? (int)t : 0;
	double signal = noise_at(x, y, z, generator) * 2.0 - 1.0 + offset;
	x *= lacunarity, y *= lacunarity, z *= lacunarity;
	double step = pow(lacunarity, -h), weight = step;
	for (int i = 1; i < octaves; i++) {
		double inc = (noise_at(x, y, z, generator) * 2.0 - 1.0 + offset) * weight;
		for (int k = power; k > 0; k--)
			inc *= signal;
		signal += inc;
		x *= lacunarity, y *= lacunarity, z *= lacunarity;
		weight *= step;
	}
	double rem = isnan(octaves) ? octaves : octaves - trunc(octaves);
	if (rem != 0.0)
		signal += rem * ((noise_at(x, y, z, generator) * 2.0 - 1.0 + offset) * weight) * signal;
	return signal;
}

/* f_ridge: x y z, lambda, octaves, omega, offset, ridge, generator. */
static double ridge(const double *a)
{
	double x = a[0], y = a[1], z = a[2], lambda = a[3], octaves = clamp_count(a[4]), omega = a[5];
	double offset = a[6], ridge = a[7];
	int generator = noise_generator_of(a[8]);
	int n = isnan(octaves) ? 0 : (int)octaves;
	double resid = isnan(octaves) ? octaves : octaves - n;
	double rscale = 1.0 / fmax(ridge, 1.0 - ridge), scale = 1.0 / fmax(offset, 1.0 - offset);
	double value = fabs(noise_at(x, y, z, generator) - ridge) * rscale - offset, total = 1.0;
	double l = lambda, o = omega;
	for (int i = 2; i <= n; i++) {
		value += o * (fabs(noise_at(x * l, y * l, z * l, generator) - ridge) * rscale - offset);
		total += o;
		l *= lambda;
		o *= omega;
	}
	if (resid != 0.0) {
		value += o * (fabs(noise_at(x * l, y * l, z * l, generator) - ridge) * rscale - offset) * resid;
		total += o * resid;
	}
	return value * scale / total;
}

/* f_ridged_mf: x y z, H, lacunarity, octaves, offset, gain, generator. POV-Ray
 * keeps its octaves' weights from the first call of the function in the scene
 * (they are its parameters' for a function called with constant ones). */
static double ridged_mf(const double *a)
{
	double x = a[0], y = a[1], z = a[2], h = a[3], lacunarity = a[4], octaves = clamp_count(a[5]);
	double offset = a[6], gain = a[7];
	int generator = noise_generator_of(a[8]);
	double signal = offset - fabs(noise_at(x, y, z, generator) * 2.0 - 1.0);
	signal *= signal;
	double result = signal, frequency = 1.0;
	for (int i = 1; i < octaves; i++) {
		x *= lacunarity, y *= lacunarity, z *= lacunarity;
		frequency *= lacunarity;
		double weight = signal * gain;
		weight = weight > 1.0 ? 1.0 : weight < 0.0 ? 0.0 : weight;
		signal = offset - fabs(noise_at(x, y, z, generator) * 2.0 - 1.0);
		signal *= signal;
		signal *= weight;
		result += signal * pow(frequency, -h);
	}
	return result;
}

double scene_noise_op(int op, const double *a)
{
	switch (op) {
	case FOP_NOISE4: return noise_at(a[0], a[1], a[2], noise_generator_of(a[3]));
	case FOP_HETERO_MF: return hetero_mf(a);
	case FOP_RIDGE: return ridge(a);
	case FOP_RIDGED_MF: return ridged_mf(a);
	default: return 0;
	}
}
