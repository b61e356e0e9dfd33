/* pattern.cl: POV-Ray 3.7's patterns, warps and noise, evaluated on the device.
 *
 * pattern_value gives the value a pattern takes at a point: the warps of the
 * pattern in order, then the pattern, then (for continuous patterns) frequency,
 * phase and wave type, each where POV-Ray 3.7 applies it, so that a mask of a
 * pattern renders POV-Ray's pixels. The noise is POV-Ray's own: its lattice
 * noise (noise_generator 1 and 2), Perlin's gradient noise (3), with the tables
 * POV-Ray builds at start-up (kernels/pattern_tables.cl). Everything is float:
 * the hashing that decides POV-Ray's exact values is integer, and the rest
 * loses at most a few float roundings against POV-Ray's doubles.
 *
 * Exported: pattern_value (= pattern_at after pattern_warp_point),
 * pattern_noise, pattern_dnoise, pattern_turbulence, pattern_dturbulence. */

#define PATTERN_PI 3.14159265358979323846f

/* ---- small helpers ---- */

/* POV-Ray's FLOOR: like floor, except that a negative whole number goes one
 * lower. Kept for quilted, which uses it. */
static inline float pattern_floor_pov(float x)
{
	return x >= 0.0f ? floor(x) : -floor(-x) - 1.0f;
}

/* POV-Ray's cycloidal(): sin(2 pi v) from v's fraction, odd around 0. */
static inline float pattern_cycloidal(float v)
{
	if (v >= 0.0f)
		return sinpi(2.0f * (v - floor(v)));
	return -sinpi(2.0f * (-(v + floor(-v))));
}

/* POV-Ray's Triangle_Wave: 0 at whole numbers, 1 halfway. */
static inline float pattern_triangle_wave(float v)
{
	float offset = v >= 0.0f ? v - floor(v) : v + 1.0f + floor(fabs(v));
	return offset >= 0.5f ? 2.0f * (1.0f - offset) : 2.0f * offset;
}

/* CLIP_DENSITY of boxed, cylindrical, planar and spherical: 1 at the centre
 * down to 0 at distance 1, and 1 again for a negative distance. */
static inline float pattern_clip_density(float r)
{
	return r < 0.0f ? 1.0f : r > 1.0f ? 0.0f : 1.0f - r;
}

/* POV-Ray's Hash3d over its hash table: every index is taken mod 4096, as the
 * macro's masks do. */
static inline int pattern_hash3(int a, int b, int c)
{
	return pattern_hash[pattern_hash[pattern_hash[a & 0xfff] ^ (b & 0xfff)] ^ (c & 0xfff)];
}

/* ---- noise ---- */

/* The lattice cell of one coordinate as POV-Ray's noise hashes it: the
 * integer part offset by 10000 and masked to 12 bits, so that negative
 * coordinates do not mirror positive ones. */
static inline int pattern_lattice(float floor_x)
{
	return ((int)floor_x + 10000) & 0xfff;
}

/* The offset into RTable's 267 values of one lattice corner (POV-Ray's
 * Hash1dRTableIndex, which indexes the interleaved table with twice it). */
static inline int pattern_corner(int hxy, int iz)
{
	return pattern_hash[(hxy ^ iz) & 0xfff] & 0xff;
}

/* One corner's contribution, POV-Ray's INCRSUMP: the corner's value (RTable's
 * half of an entry) plus a gradient from the next three entries. */
static inline float pattern_incr(int k, float s, float x, float y, float z)
{
	return s * (0.5f * pattern_rtable[k] + pattern_rtable[k + 1] * x
	            + pattern_rtable[k + 2] * y + pattern_rtable[k + 3] * z);
}

/* noise_generator 3: Perlin's gradient noise with POV-Ray's tables, in about
 * [-1, 1]. POV-Ray shifts the point by 10000000.023157213 in double before
 * taking floors; 10000000 is 1664 mod 2048, so the shift is split into the
 * fraction, added in float, and 1664 added to the integer part. */
static inline float pattern_solid_noise(float3 p)
{
	const float roll = 0.023157213f;
	float3 t = p + (float3)(roll, roll, roll);
	float3 f = floor(t);
	float3 r0 = t - f;
	float3 r1 = r0 - 1.0f;
	int bx0 = ((int)f.x + 1664) & 2047, bx1 = (bx0 + 1) & 2047;
	int by0 = ((int)f.y + 1664) & 2047, by1 = (by0 + 1) & 2047;
	int bz0 = ((int)f.z + 1664) & 2047, bz1 = (bz0 + 1) & 2047;
	int i = pattern_perm[bx0], j = pattern_perm[bx1];
	int b00 = pattern_perm[(i + by0) & 2047], b10 = pattern_perm[(j + by0) & 2047];
	int b01 = pattern_perm[(i + by1) & 2047], b11 = pattern_perm[(j + by1) & 2047];
	float3 s = r0 * r0 * (3.0f - 2.0f * r0);
#define PATTERN_GRAD_AT(b, rx, ry, rz) \
	(pattern_grad[3 * ((b) & 2047)] * (rx) + pattern_grad[3 * ((b) & 2047) + 1] * (ry) \
	 + pattern_grad[3 * ((b) & 2047) + 2] * (rz))
	float u = PATTERN_GRAD_AT(b00 + bz0, r0.x, r0.y, r0.z);
	float v = PATTERN_GRAD_AT(b10 + bz0, r1.x, r0.y, r0.z);
	float a = mix(u, v, s.x);
	u = PATTERN_GRAD_AT(b01 + bz0, r0.x, r1.y, r0.z);
	v = PATTERN_GRAD_AT(b11 + bz0, r1.x, r1.y, r0.z);
	float b = mix(u, v, s.x);
	float c = mix(a, b, s.y);
	u = PATTERN_GRAD_AT(b00 + bz1, r0.x, r0.y, r1.z);
	v = PATTERN_GRAD_AT(b10 + bz1, r1.x, r0.y, r1.z);
	a = mix(u, v, s.x);
	u = PATTERN_GRAD_AT(b01 + bz1, r0.x, r1.y, r1.z);
	v = PATTERN_GRAD_AT(b11 + bz1, r1.x, r1.y, r1.z);
	b = mix(u, v, s.x);
	float d = mix(a, b, s.y);
#undef PATTERN_GRAD_AT
	return mix(c, d, s.z);
}

/* The lattice cell of p that POV-Ray's Noise and DNoise both start from:
 * the offsets from its two corners, the smoothstep weights, the hashes of its
 * four columns and its z index. */
typedef struct {
	float3 f0, f1, s, t;
	int h00, h10, h01, h11, iz;
} pattern_cell_corners;

static inline pattern_cell_corners pattern_corners(float3 p)
{
	pattern_cell_corners c;
	float3 fl = floor(p);
	c.f0 = p - fl;
	c.f1 = c.f0 - 1.0f;
	int ix = pattern_lattice(fl.x), iy = pattern_lattice(fl.y);
	c.iz = pattern_lattice(fl.z);
	c.s = c.f0 * c.f0 * (3.0f - 2.0f * c.f0);
	c.t = 1.0f - c.s;
	c.h00 = pattern_hash[(pattern_hash[ix] ^ iy) & 0xfff];
	c.h10 = pattern_hash[(pattern_hash[(ix + 1) & 0xfff] ^ iy) & 0xfff];
	c.h01 = pattern_hash[(pattern_hash[ix] ^ (iy + 1)) & 0xfff];
	c.h11 = pattern_hash[(pattern_hash[(ix + 1) & 0xfff] ^ (iy + 1)) & 0xfff];
	return c;
}

/* POV-Ray's Noise: a value in [0, 1]. Generator 1 is the original lattice
 * noise (centred on 0.5, clipped), 2 the same stretched to fill [0, 1] better
 * (POV-Ray 3.7's default), 3 Perlin's gradient noise rescaled. */
static float pattern_noise(float3 p, int generator)
{
	if (generator == 3)
		return clamp(0.5f * (1.59f * pattern_solid_noise(p) + 0.985f), 0.0f, 1.0f);
	pattern_cell_corners cc = pattern_corners(p);
	float3 f0 = cc.f0, f1 = cc.f1, s = cc.s, t = cc.t;
	int h00 = cc.h00, h10 = cc.h10, h01 = cc.h01, h11 = cc.h11, iz = cc.iz;
	float sum = pattern_incr(pattern_corner(h00, iz), t.x * t.y * t.z, f0.x, f0.y, f0.z)
	          + pattern_incr(pattern_corner(h10, iz), s.x * t.y * t.z, f1.x, f0.y, f0.z)
	          + pattern_incr(pattern_corner(h01, iz), t.x * s.y * t.z, f0.x, f1.y, f0.z)
	          + pattern_incr(pattern_corner(h11, iz), s.x * s.y * t.z, f1.x, f1.y, f0.z)
	          + pattern_incr(pattern_corner(h00, iz + 1), t.x * t.y * s.z, f0.x, f0.y, f1.z)
	          + pattern_incr(pattern_corner(h10, iz + 1), s.x * t.y * s.z, f1.x, f0.y, f1.z)
	          + pattern_incr(pattern_corner(h01, iz + 1), t.x * s.y * s.z, f0.x, f1.y, f1.z)
	          + pattern_incr(pattern_corner(h11, iz + 1), s.x * s.y * s.z, f1.x, f1.y, f1.z);
	/* The range POV-Ray measured for the raw sum is [-1.05242, 0.988997]. */
	if (generator == 2)
		sum = (sum + 1.05242f) * 0.48985582f;
	else
		sum += 0.5f;
	return clamp(sum, 0.0f, 1.0f);
}

/* One corner of POV-Ray's DNoise: the three components use entries k, k + 4
 * and k + 8 of RTable (8 and 16 in the interleaved table). */
static inline float3 pattern_dincr(int k, float s, float x, float y, float z)
{
	return (float3)(pattern_incr(k, s, x, y, z), pattern_incr(k + 4, s, x, y, z),
	                pattern_incr(k + 8, s, x, y, z));
}

/* POV-Ray's DNoise: a vector-valued lattice noise, components in about
 * [-1, 1], for turbulence, wood and (later) normals. POV-Ray 3.7 uses this one
 * whatever the noise_generator: generator is accepted and ignored. */
static float3 pattern_dnoise(float3 p, int generator)
{
	(void)generator;
	pattern_cell_corners cc = pattern_corners(p);
	float3 f0 = cc.f0, f1 = cc.f1, s = cc.s, t = cc.t;
	int h00 = cc.h00, h10 = cc.h10, h01 = cc.h01, h11 = cc.h11, iz = cc.iz;
	return pattern_dincr(pattern_corner(h00, iz), t.x * t.y * t.z, f0.x, f0.y, f0.z)
	     + pattern_dincr(pattern_corner(h10, iz), s.x * t.y * t.z, f1.x, f0.y, f0.z)
	     + pattern_dincr(pattern_corner(h11, iz), s.x * s.y * t.z, f1.x, f1.y, f0.z)
	     + pattern_dincr(pattern_corner(h01, iz), t.x * s.y * t.z, f0.x, f1.y, f0.z)
	     + pattern_dincr(pattern_corner(h01, iz + 1), t.x * s.y * s.z, f0.x, f1.y, f1.z)
	     + pattern_dincr(pattern_corner(h11, iz + 1), s.x * s.y * s.z, f1.x, f1.y, f1.z)
	     + pattern_dincr(pattern_corner(h10, iz + 1), s.x * t.y * s.z, f1.x, f0.y, f1.z)
	     + pattern_dincr(pattern_corner(h00, iz + 1), t.x * t.y * s.z, f0.x, f0.y, f1.z);
}

/* POV-Ray's Turbulence: octaves of noise at growing frequencies (lambda) and
 * shrinking weights (omega). Generators 2 and 3 stretch each octave by 2 and
 * shift it by -0.5, the first clipped to [0, 1], the others not. */
static float pattern_turbulence(float3 p, float omega, float lambda, int octaves, int generator)
{
	float value = pattern_noise(p, generator);
	if (generator > 1)
		value = clamp(2.0f * value - 0.5f, 0.0f, 1.0f);
	float l = lambda, o = omega;
	for (int i = 2; i <= octaves; i++) {
		float n = pattern_noise(p * l, generator);
		value += o * (generator > 1 ? 2.0f * n - 0.5f : n);
		l *= lambda;
		o *= omega;
	}
	return value;
}

/* POV-Ray's DTurbulence: the same sum over DNoise, unstretched. */
static float3 pattern_dturbulence(float3 p, float omega, float lambda, int octaves)
{
	float3 value = pattern_dnoise(p, 0);
	float l = lambda, o = omega;
	for (int i = 2; i <= octaves; i++) {
		value += o * pattern_dnoise(p * l, 0);
		l *= lambda;
		o *= omega;
	}
	return value;
}

/* The internal functions of functions.inc that sum octaves of Noise
 * (FOP_NOISE4, FOP_HETERO_MF, FOP_RIDGE, FOP_RIDGED_MF of the scene's
 * functions): POV-Ray's f_noise_generator, f_hetero_mf, f_ridge and
 * f_ridged_mf, in real, each octave's point made float for the noise. Their
 * host twins (scene_noise.c) say why: a generator past int or NaN is 0, and
 * counts are clamped to [-FUNCTION_OCTAVES_MAX, FUNCTION_OCTAVES_MAX] (a NaN
 * count loops none), so no parameter makes a loop long. */
#define FUNCTION_OCTAVES_MAX 64.0

static inline int function_noise_generator(real p)
{
	return p > (real)-2147483648.0 && p < (real)2147483648.0 ? (int)p & 3 : 0;
}

static inline real function_clamp_count(real n)
{
	return isnan(n) ? n : fmin(fmax(n, (real)-FUNCTION_OCTAVES_MAX), (real)FUNCTION_OCTAVES_MAX);
}

static inline real function_noise_at(real x, real y, real z, int generator)
{
	return (real)pattern_noise((float3)((float)x, (float)y, (float)z), generator);
}

static real function_noise4(real x, real y, real z, real generator)
{
	return function_noise_at(x, y, z, function_noise_generator(generator));
}

/* x y z, H, lacunarity, octaves, offset, T (an exponent), generator. */
static real function_hetero_mf(real x, real y, real z, real h, real lacunarity, real octaves_p, real offset,
                               real t_p, real generator_p)
{
	real octaves = function_clamp_count(octaves_p), t = function_clamp_count(t_p);
	int generator = function_noise_generator(generator_p);
	int power = t > 0 ? (int)t : 0;
	real signal = function_noise_at(x, y, z, generator) * 2 - 1 + offset;
	x *= lacunarity, y *= lacunarity, z *= lacunarity;
	real step = pow(lacunarity, -h), weight = step;
	for (int i = 1; i < octaves; i++) {
		real inc = (function_noise_at(x, y, z, generator) * 2 - 1 + offset) * weight;
		for (int k = power; k > 0; k--)
			inc *= signal;
		signal += inc;
		x *= lacunarity, y *= lacunarity, z *= lacunarity;
		weight *= step;
	}
	real rem = isnan(octaves) ? octaves : octaves - trunc(octaves);
	if (rem != 0)
		signal += rem * ((function_noise_at(x, y, z, generator) * 2 - 1 + offset) * weight) * signal;
	return signal;
}

/* x y z, lambda, octaves, omega, offset, ridge, generator. */
static real function_ridge(real x, real y, real z, real lambda, real octaves_p, real omega, real offset, real ridge,
                           real generator_p)
{
	real octaves = function_clamp_count(octaves_p);
	int generator = function_noise_generator(generator_p);
	int n = isnan(octaves) ? 0 : (int)octaves;
	real resid = isnan(octaves) ? octaves : octaves - n;
	real rscale = 1 / fmax(ridge, 1 - ridge), scale = 1 / fmax(offset, 1 - offset);
	real value = fabs(function_noise_at(x, y, z, generator) - ridge) * rscale - offset, total = 1;
	real l = lambda, o = omega;
	for (int i = 2; i <= n; i++) {
		value += o * (fabs(function_noise_at(x * l, y * l, z * l, generator) - ridge) * rscale - offset);
		total += o;
		l *= lambda;
		o *= omega;
	}
	if (resid != 0) {
		value += o * (fabs(function_noise_at(x * l, y * l, z * l, generator) - ridge) * rscale - offset) * resid;
		total += o * resid;
	}
	return value * scale / total;
}

/* x y z, H, lacunarity, octaves, offset, gain, generator. */
static real function_ridged_mf(real x, real y, real z, real h, real lacunarity, real octaves_p, real offset,
                               real gain, real generator_p)
{
	real octaves = function_clamp_count(octaves_p);
	int generator = function_noise_generator(generator_p);
	real signal = offset - fabs(function_noise_at(x, y, z, generator) * 2 - 1);
	signal *= signal;
	real result = signal, frequency = 1;
	for (int i = 1; i < octaves; i++) {
		x *= lacunarity, y *= lacunarity, z *= lacunarity;
		frequency *= lacunarity;
		real weight = signal * gain;
		weight = weight > 1 ? (real)1 : weight < 0 ? (real)0 : weight;
		signal = offset - fabs(function_noise_at(x, y, z, generator) * 2 - 1);
		signal *= signal;
		signal *= weight;
		result += signal * pow(frequency, -h);
	}
	return result;
}

/* A turbulence warp's own parameters. */
static inline float pattern_warp_turbulence(global const dev_warp *w, int generator, float3 p)
{
	return pattern_turbulence(p, w->a.w, w->b.x, (int)w->b.y, generator);
}

/* ---- warps ---- */

/* The angle of (x, z) from the x axis, over a turn, as POV-Ray finds it. */
static inline float pattern_warp_turn(float x, float z, float len)
{
	float theta = z == 0.0f ? (x > 0.0f ? 0.0f : PATTERN_PI) : acos(x / len);
	if (z < 0.0f)
		theta = 2.0f * PATTERN_PI - theta;
	return theta / (2.0f * PATTERN_PI);
}

/* A mapping warp's surface coordinates (x, y) and distance z: both
 * coordinates scaled by the distance to the power dist_exp (0: not at all),
 * then turned to the warp's orientation, as POV-Ray's warps end. */
static inline float3 pattern_warp_oriented(global const dev_warp *w, float x, float y, float z, float dist_exp)
{
	if (dist_exp != 0.0f) {
		float k = dist_exp == 1.0f ? z : pow(z, dist_exp);
		x *= k;
		y *= k;
	}
	float3 o = w->a.xyz;
	if (o.x == 0.0f && o.y == 0.0f && o.z == 1.0f)
		return (float3)(x, y, z);
	return (float3)(o.x * z + o.y * x + o.z * x, o.x * y - o.y * z + o.z * y, -o.x * x + o.y * y + o.z * z);
}

/* POV-Ray 3.7's mapping warps (warps.cpp): the surface's coordinates into x and
 * y, the distance into z, then turned to the orientation. A point on the
 * axis (or at the centre) stays where it is, as POV-Ray leaves it. */
static float3 pattern_warp_mapping(global const dev_warp *w, float3 p)
{
	float x = p.x, y = p.y, z = p.z, dist_exp = w->a.w;
	if (w->kind == WARP_CUBIC) {
		float ax = fabs(x), ay = fabs(y), az = fabs(z);
		if (ax == 0.0f && ay == 0.0f && az == 0.0f)
			return p;
		if (x >= 0.0f && x >= ay && x >= az)
			return (float3)(0.75f - 0.25f * (z / x + 1.0f) / 2.0f, 1.0f / 3.0f + (y / x + 1.0f) / 6.0f, x);
		if (y >= 0.0f && y >= ax && y >= az)
			return (float3)(0.25f + 0.25f * (x / y + 1.0f) / 2.0f, 1.0f - (z / y + 1.0f) / 6.0f, y);
		if (z >= 0.0f && z >= ax && z >= ay)
			return (float3)(0.25f + 0.25f * (x / z + 1.0f) / 2.0f, 1.0f / 3.0f + (y / z + 1.0f) / 6.0f, z);
		if (x < 0.0f && x <= -ay && x <= -az)
			return (float3)(0.25f * (z / -x + 1.0f) / 2.0f, 1.0f / 3.0f + (y / -x + 1.0f) / 6.0f, -x);
		if (y < 0.0f && y <= -ax && y <= -az)
			return (float3)(0.25f + 0.25f * (x / -y + 1.0f) / 2.0f, (z / -y + 1.0f) / 6.0f, -y);
		return (float3)(1.0f - 0.25f * (x / -z + 1.0f) / 2.0f, 1.0f / 3.0f + (y / -z + 1.0f) / 6.0f, -z);
	}
	if (w->kind == WARP_PLANAR)
		return pattern_warp_oriented(w, x, y, dist_exp, 0.0f);   /* dist_exp holds the offset */
	if (w->kind == WARP_CYLINDRICAL) {
		float len = sqrt(x * x + z * z);
		if (len == 0.0f)
			return p;
		float theta = pattern_warp_turn(x, z, len);
		if (dist_exp != 0.0f)
			theta *= dist_exp == 1.0f ? len : pow(len, dist_exp);
		return pattern_warp_oriented(w, theta, y, len, 0.0f);
	}
	if (w->kind == WARP_SPHERICAL) {
		float dist = sqrt(x * x + y * y + z * z);
		if (dist == 0.0f)
			return p;
		x /= dist;
		y /= dist;
		z /= dist;
		float phi = 0.5f + asin(clamp(y, -1.0f, 1.0f)) / PATTERN_PI, len = sqrt(x * x + z * z);
		float theta = len == 0.0f ? 0.0f : pattern_warp_turn(x, z, len);
		return pattern_warp_oriented(w, theta, phi, dist, dist_exp);
	}
	float len = sqrt(x * x + z * z);   /* toroidal */
	if (len == 0.0f)
		return p;
	float theta = pattern_warp_turn(x, z, len);
	float rx = len - w->b.x;
	len = sqrt(rx * rx + y * y);
	float phi = len == 0.0f ? 0.0f : acos(clamp(-rx / len, -1.0f, 1.0f));   /* on the core circle: 0 */
	if (y > 0.0f)
		phi = 2.0f * PATTERN_PI - phi;
	return pattern_warp_oriented(w, theta, phi / (2.0f * PATTERN_PI), len, dist_exp);
}

static inline float3 pattern_warp(global const dev_warp *w, float3 p)
{
	if (w->kind == WARP_TURBULENCE) {
		float3 d = pattern_dturbulence(p, w->a.w, w->b.x, (int)w->b.y);
		return p + d * w->a.xyz;
	}
	if (w->kind == WARP_REPEAT) {
		/* The one non-zero component of the repeat vector is the axis. */
		float3 r = w->a.xyz;
		int axis = r.x != 0.0f ? 0 : r.y != 0.0f ? 1 : 2;
		float width = axis == 0 ? r.x : axis == 1 ? r.y : r.z;
		float pa = axis == 0 ? p.x : axis == 1 ? p.y : p.z;
		float block = floor(pa / width);
		float3 q = p;
		float qa = pa - block * width;
		int odd = (int)block & 1;
		int flip_axis = (axis == 0 ? w->c.x : axis == 1 ? w->c.y : w->c.z) != 0.0f;
		if (odd) {
			q.x = w->c.x != 0.0f ? -q.x : q.x;
			q.y = w->c.y != 0.0f ? -q.y : q.y;
			q.z = w->c.z != 0.0f ? -q.z : q.z;
			if (flip_axis)
				qa = width - qa;
		}
		if (axis == 0)
			q.x = qa;
		else if (axis == 1)
			q.y = qa;
		else
			q.z = qa;
		return q + block * w->b.xyz;
	}
	if (w->kind == WARP_TRANSFORM) {
		float4 q = (float4)(p, 1.0f);
		return (float3)(dot(w->a, q), dot(w->b, q), dot(w->c, q));
	}
	if (w->kind >= WARP_PLANAR)
		return pattern_warp_mapping(w, p);
	if (w->kind == WARP_BLACK_HOLE) {
		float3 centre = w->a.xyz;
		if (w->c.w != 0.0f) {
			/* Repeated: the hole of the block the point is in, blocks
			 * counted from 0 along each axis with a repeat. */
			float3 rep = w->c.xyz;
			float3 block = (float3)(rep.x >= 1e-10f ? floor(p.x / rep.x) : 0.0f,
			                        rep.y >= 1e-10f ? floor(p.y / rep.y) : 0.0f,
			                        rep.z >= 1e-10f ? floor(p.z / rep.z) : 0.0f);
			/* its turbulence moves each block's hole by POV-Ray's WarpRands
			 * (PatternRands' sequence) at the block's hash */
			float3 b = clamp(block, -1.0e9f, 1.0e9f);   /* an int's range: only the low bits hash */
			int seed = pattern_hash3((int)b.x, (int)b.y, (int)b.z);
			centre += (float3)(pattern_rands[seed], pattern_rands[seed + 1], pattern_rands[seed + 2]) * w->d.xyz;
			centre += rep * block;
		}
		float3 delta = p - centre;
		float len = length(delta);
		float radius = w->a.w;
		if (len >= radius)
			return p;
		float strength = pow((radius - len) / radius, w->b.y) * w->b.x;
		strength = fmin(strength, 1.0f);
		return p + delta * (w->b.z != 0.0f ? -strength : strength);
	}
	return p;
}

/* ---- the patterns, as POV-Ray 3.7's pattern.cpp computes them ---- */

static inline float pattern_agate(float3 p, global const dev_warp *turb, float agate_turb, int generator)
{
	/* POV-Ray's defaults should the turbulence be missing. */
	float t = turb ? pattern_warp_turbulence(turb, generator, p)
	               : pattern_turbulence(p, 0.5f, 2.0f, 6, generator);
	float noise = 0.5f * (pattern_cycloidal(1.3f * agate_turb * t + 1.1f * p.z) + 1.0f);
	return noise < 0.0f ? 0.0f : pow(fmin(noise, 1.0f), 0.77f);
}

/* Whether a coordinate of brick falls in the mortar: POV-Ray tests
 * frac((x + 1e-10 + mortar) / size) <= mortar / size in double, which holds
 * exactly when x mod size >= size - mortar - 1e-10. Tested this way in float,
 * where the 1e-10 vanishes and would put x = 0, a common plane, in the mortar. */
static inline int pattern_brick_mortar(float x, float size, float mortar)
{
	return x - size * floor(x / size) >= size - mortar;
}

/* Brick: rows of height size.y, every other row shifted by half a brick along
 * x and z. POV-Ray's row test frac((y + mortar) / (2 size.y)) <= 0.5 changes
 * only inside horizontal mortar, so float cannot misplace it. */
static inline float pattern_brick(float3 p, float4 size_mortar)
{
	float3 size = size_mortar.xyz;
	float mortar = size_mortar.w;
	if (pattern_brick_mortar(p.y, size.y, mortar))
		return 0.0f;
	float row = (p.y + mortar) / (2.0f * size.y);
	int odd = row - floor(row) > 0.5f;
	float half_x = odd ? 0.5f * size.x : 0.0f, half_z = odd ? 0.0f : 0.5f * size.z;
	if (pattern_brick_mortar(p.x + half_x, size.x, mortar) || pattern_brick_mortar(p.z + half_z, size.z, mortar))
		return 0.0f;
	return 1.0f;
}

/* The integer cell of p as POV-Ray finds it with floor(x + 1e-10) in double:
 * a point on a cell's face belongs to the cell above. Hit points in float are
 * off by a few ulps of the coordinates, so a face at an integer (a plane at
 * y = 0) would flicker between two cells: the tolerance here is the points'
 * own precision instead. */
static inline float3 pattern_cell(float3 p)
{
	float eps = 1e-5f * fmax(1.0f, fmax(fabs(p.x), fmax(fabs(p.y), fabs(p.z))));
	return floor(p + eps);
}

/* The random point of POV-Ray's crackle and facets in the unit cell
 * (cx, cy, cz). */
static inline float3 pattern_cell_point(int cx, int cy, int cz)
{
	int seed = pattern_hash3(cx, cy, cz);
	return (float3)((float)cx + pattern_rands[seed], (float)cy + pattern_rands[seed + 1],
	                (float)cz + pattern_rands[seed + 2]);
}

static inline float pattern_cells(float3 p)
{
	float3 c = pattern_cell(p);
	int h = pattern_hash3((int)c.x, (int)c.y, (int)c.z);
	return fmin(pattern_rands[h], 1.0f);
}

static inline float pattern_checker(float3 p)
{
	float3 c = pattern_cell(p);
	int v = (int)(c.x + c.y + c.z);
	return (v & 1) ? 1.0f : 0.0f;
}

/* The distance of crackle's metric, before the root. */
static inline float pattern_metric(float3 d, float metric)
{
	d = fabs(d);
	if (metric == 2.0f)
		return dot(d, d);
	if (metric == 1.0f)
		return d.x + d.y + d.z;
	return pow(d.x, metric) + pow(d.y, metric) + pow(d.z, metric);
}

/* Crackle: one random point per unit cube (POV-Ray's IntPickInCube); the three
 * nearest among the 81 cubes within a "knight's move" of the point's cube, in
 * POV-Ray's order, combined by form, or the noise at the nearest (solid). */
static inline float pattern_crackle(float3 p, float4 form_metric, float4 offset_solid, int generator)
{
	float metric = form_metric.w;
	float offset = offset_solid.x;
	int fx = (int)floor(p.x - 1e-10f), fy = (int)floor(p.y - 1e-10f), fz = (int)floor(p.z - 1e-10f);
	float d1 = MAXFLOAT, d2 = MAXFLOAT, d3 = MAXFLOAT;
	float3 nearest = (float3)(0.0f);
	for (int ax = -2; ax <= 2; ax++)
		for (int ay = -2; ay <= 2; ay++)
			for (int az = -2; az <= 2; az++) {
				if ((abs(ax) == 2) + (abs(ay) == 2) + (abs(az) == 2) > 1)
					continue;
				int cx = fx + ax, cy = fy + ay, cz = fz + az;
				float3 c = pattern_cell_point(cx, cy, cz);
				float d = pattern_metric(c - p, metric);
				/* POV-Ray sorts its first three, then keeps the three
				 * smallest; strict comparisons keep its choice on ties. */
				if (d < d1) {
					d3 = d2;
					d2 = d1;
					d1 = d;
					nearest = c;
				} else if (d < d2) {
					d3 = d2;
					d2 = d;
				} else if (d < d3) {
					d3 = d;
				}
			}
	if (offset != 0.0f) {
		float o = metric == 2.0f ? offset * offset : metric == 1.0f ? offset : pow(offset, metric);
		d1 += o;
		d2 += o;
		d3 += o;
	}
	float tf;
	if (offset_solid.y != 0.0f)
		tf = pattern_noise(nearest, generator);
	else if (metric == 2.0f)
		tf = form_metric.x * sqrt(d1) + form_metric.y * sqrt(d2) + form_metric.z * sqrt(d3);
	else if (metric == 1.0f)
		tf = form_metric.x * d1 + form_metric.y * d2 + form_metric.z * d3;
	else
		tf = form_metric.x * pow(d1, 1.0f / metric) + form_metric.y * pow(d2, 1.0f / metric)
		   + form_metric.z * pow(d3, 1.0f / metric);
	return clamp(tf, 0.0f, 1.0f);
}

static inline float pattern_cubic(float3 p)
{
	float3 a = fabs(p);
	if (p.x >= 0.0f && p.x >= a.y && p.x >= a.z)
		return 0.0f;
	if (p.y >= 0.0f && p.y >= a.x && p.y >= a.z)
		return 1.0f;
	if (p.z >= 0.0f && p.z >= a.x && p.z >= a.y)
		return 2.0f;
	if (p.x < 0.0f && p.x <= -a.y && p.x <= -a.z)
		return 3.0f;
	if (p.y < 0.0f && p.y <= -a.x && p.y <= -a.z)
		return 4.0f;
	return 5.0f;
}

static inline float pattern_gradient(float3 p, float3 axis)
{
	float r = dot(p, axis);
	return r > 1.0f ? fmod(r, 1.0f) : r;
}

static inline float pattern_granite(float3 p, int generator)
{
	float noise = 0.0f, freq = 1.0f;
	float3 q = p * 4.0f;
	for (int i = 0; i < 6; i++, freq *= 2.0f) {
		float n = pattern_noise(q * freq, generator);
		float t = generator == 1 ? fabs(0.5f - n) : fmin(fabs(1.0f - 2.0f * n), 0.5f);
		noise += t / freq;
	}
	return noise;
}

/* Hexagon in the x-z plane: the grid is mapped into 6 by 6 blocks of half a
 * side by sqrt(3)/2, in which the colour follows from the block, or from the
 * side of the block's diagonal. */
static inline float pattern_hexagon(float3 p)
{
	float x = fabs(p.x);
	float z = p.z < 0.0f ? 5.196152424f - fabs(p.z) : p.z;   /* no mirror across x */
	float xs = x / 0.5f, zs = z / 0.866025404f;
	xs -= floor(xs / 6.0f) * 6.0f;
	zs -= floor(zs / 6.0f) * 6.0f;
	int xm = (int)pattern_floor_pov(xs) % 6, zm = (int)pattern_floor_pov(zs) % 6;
	float value = 0.0f;
	if (xm == 0 || xm == 5) {
		value = (zm == 0 || zm == 5) ? 0.0f : (zm == 1 || zm == 2) ? 1.0f : 2.0f;
	} else if (xm == 2 || xm == 3) {
		value = (zm == 0 || zm == 1) ? 2.0f : (zm == 2 || zm == 3) ? 0.0f : 1.0f;
	} else {
		float xl = xs - (float)xm, zl = zs - (float)zm;
		if ((xm + zm) % 2 == 1)
			xl = 1.0f - xl;
		if (xl == 0.0f)
			xl = 0.0001f;
		if (zl / xl < 1.0f)
			value = (zm == 0 || zm == 3) ? 0.0f : (zm == 2 || zm == 5) ? 1.0f : 2.0f;
		else
			value = (zm == 0 || zm == 3) ? 2.0f : (zm == 2 || zm == 5) ? 0.0f : 1.0f;
	}
	return value;
}

static inline float pattern_leopard(float3 p)
{
	float v = (sin(p.x) + sin(p.y) + sin(p.z)) / 3.0f;
	return v * v;
}

static inline float pattern_quilted(float3 p, float c0, float c1)
{
	float3 v = (float3)(p.x - pattern_floor_pov(p.x), p.y - pattern_floor_pov(p.y),
	                    p.z - pattern_floor_pov(p.z)) - 0.5f;
	float t = length(v);
	/* POV-Ray's quilt_cubic: a Bezier from 0 to 1 with the two controls. */
	float it = 1.0f - t;
	t = (t * t * t + 3.0f * t * it * it * c0 + 3.0f * t * t * it * c1) * 1.154700538f;
	v *= t;
	return (fabs(v.x) + fabs(v.y) + fabs(v.z)) / 3.0f;
}

static inline float pattern_radial(float3 p)
{
	if (fabs(p.x) < 0.001f && fabs(p.z) < 0.001f)
		return 0.25f;
	return 0.25f + (atan2(p.x, p.z) + PATTERN_PI) / (2.0f * PATTERN_PI);
}

/* The angle around the z axis spiral1 and spiral2 turn with, 0 to 2 pi. */
static inline float pattern_spiral_phi(float x, float y, float rad)
{
	if (rad == 0.0f)
		return 0.0f;
	return x < 0.0f ? 1.5f * PATTERN_PI - asin(y / rad) : 0.5f * PATTERN_PI + asin(y / rad);
}

static inline float pattern_square(float3 p)
{
	int x = (int)floor(p.x), z = (int)floor(p.z);
	if (x & 1)
		return (z & 1) ? 2.0f : 3.0f;
	return (z & 1) ? 1.0f : 0.0f;
}

/* Triangular in the x-z plane: space folded into a 3 by sqrt(3) rectangle,
 * mirrored about its middle, and the slopes of the point from the corners
 * decide among the six triangles. */
static inline float pattern_triangular(float3 p)
{
	const float sqrt3 = 1.7320508075688772f;
	float xs = p.x - 3.0f * floor(p.x / 3.0f);
	float zs = p.z - sqrt3 * floor(p.z / sqrt3);
	int a = (int)floor(xs);
	xs -= (float)a;
	int b = zs < 0.5f * sqrt3 ? 0 : 1;
	if (b)
		zs = sqrt3 - zs;
	float k = 1.0f - xs;
	float answer = 1.0f;
	if (xs != 0.0f && k != 0.0f) {
		int c = (zs / xs < sqrt3 ? 1 : 0) + (zs / k < sqrt3 ? 2 : 0);
		answer = c == 3 ? 0.0f : c == 2 ? 1.0f : 3.0f;
	}
	int mask = (int)answer;
	answer = (mask & 1) ? fmod(answer + 2.0f * a, 6.0f) : fmod(6.0f + answer - 2.0f * a, 6.0f);
	return b ? 5.0f - answer : answer;
}

/* Waves and ripples share POV-Ray's wave sources: source i is the direction of
 * DNoise at (i, 0, 0), its frequency a draw of POV-Ray's LCG started from
 * -560851967 (Initialize_Waves). pattern_wave_source gives source i and
 * its frequency, taking the sources in order from *r = PATTERN_WAVE_SEED. */
#define PATTERN_WAVE_SEED ((uint)-560851967)
static inline float3 pattern_wave_source(int i, uint *r, float *wf)
{
	*r = *r * 1812433253u + 12345u;
	*wf = (float)((*r >> 16) & 0x7fff) * 0.000030518509476f + 0.01f;
	return normalize(pattern_dnoise((float3)((float)i, 0.0f, 0.0f), 0));
}

static inline float pattern_waves(float3 p, int ripples, int n_waves, float frequency, float phase)
{
	uint r = PATTERN_WAVE_SEED;
	float scalar = 0.0f;
	for (int i = 0; i < n_waves; i++) {
		float wf;
		float3 src = pattern_wave_source(i, &r, &wf);
		float len = length(p - src);
		if (len == 0.0f)
			len = 1.0f;
		if (ripples)
			scalar += pattern_cycloidal(len * frequency + phase);
		else
			scalar += pattern_cycloidal(len * frequency * wf + phase) / wf;
	}
	if (ripples)
		return 0.5f * (1.0f + scalar / (float)n_waves);
	return 0.2f * (2.5f + scalar / (float)n_waves);
}

static inline float pattern_wood(float3 p, global const dev_warp *turb)
{
	float2 q = (float2)(0.0f);
	if (turb) {
		float3 t = pattern_dturbulence(p, turb->a.w, turb->b.x, (int)turb->b.y);
		q.x = pattern_cycloidal((p.x + t.x) * turb->a.x);
		q.y = pattern_cycloidal((p.y + t.y) * turb->a.y);
	}
	q += p.xy;
	return length(q);
}

static inline float pattern_wrinkles(float3 p, int generator)
{
	float lambda = 2.0f, omega = 0.5f;
	float n = pattern_noise(p, generator);
	float value = generator > 1 ? clamp(2.0f * n - 0.5f, 0.0f, 1.0f) : n;
	for (int i = 1; i < 10; i++) {
		n = pattern_noise(p * lambda, generator);
		value += omega * (generator > 1 ? clamp(2.0f * n - 0.5f, 0.0f, 1.0f) : n);
		lambda *= 2.0f;
		omega *= 0.5f;
	}
	return value / 2.0f;
}

/* Frequency, phase and wave type, as POV-Ray's Evaluate_TPat applies them to
 * a continuous pattern. POV-Ray wraps with 1.00001, not 1. */
static inline float pattern_wave(global const dev_pattern *pt, float v)
{
	if (pt->frequency != 0.0f)
		v = fmod(v * pt->frequency + pt->phase, 1.00001f);
	if (v < 0.0f)
		v -= floor(v);   /* a negative frequency */
	switch (pt->wave) {
	case WAVE_SINE:
		return (1.0f + pattern_cycloidal(v)) * 0.5f;
	case WAVE_TRIANGLE:
		return pattern_triangle_wave(v);
	case WAVE_SCALLOP:
		return fabs(pattern_cycloidal(v * 0.5f));
	case WAVE_CUBIC:
		return v * v * (3.0f - 2.0f * v);
	case WAVE_POLY:
		return pow(v, pt->wave_exponent);
	default:
		return v;
	}
}

/* The warps of pt applied in order to p, a point in the pattern's space
 * (pt->rows already applied): POV-Ray's Warp_EPoint. Marble and wood read
 * their classic turbulence themselves and never apply it as a warp. */
static float3 pattern_warp_point(global const dev_pattern *pt, global const dev_warp *warps, float3 p)
{
	int own_turb = pt->kind == PATTERN_MARBLE || pt->kind == PATTERN_WOOD;
	for (int i = 0; i < pt->warp_count; i++) {
		global const dev_warp *w = &warps[pt->warp_first + i];
		if (own_turb && w->kind == WARP_TURBULENCE && w->classic)
			continue;
		p = pattern_warp(w, p);
	}
	return clamp(p, -1.0e17f, 1.0e17f);
}

/* POV-Ray's wrap of slope's value into [0, 1), 1 itself kept (its EPSILON
 * below 1 is 1 in float). */
static inline float pattern_slope_wrap(float v)
{
	if (v == 1.0f)
		return v;
	return v < 0.0f ? 1.0f + fmod(v, 1.0f) : fmod(v, 1.0f);
}

/* slope (SlopePattern::EvaluateRaw): how far the unit normal n turns toward
 * the slope's direction, 0 (away) to 1 (along it), blended with the altitude,
 * p along the altitude's direction; each optionally rescaled by its range. */
static inline float pattern_slope(global const dev_pattern *pt, float3 p, float3 n)
{
	float3 s = pt->params[0].xyz, a = pt->params[1].xyz;
	float slen = length(s), alen = length(a);
	float v1 = slen > 0.0f ? clamp(dot(n, s) / slen, -1.0f, 1.0f) : 0.0f;
	v1 = (asin(v1) / PATTERN_PI * 2.0f + 1.0f) * 0.5f;
	if (pt->params[1].w != 0.0f)
		v1 = (v1 - pt->params[0].w) / pt->params[1].w;
	if (alen == 0.0f)
		return pattern_slope_wrap(v1);
	float v2 = dot(p, a) / alen;
	if (pt->normal.z != 0.0f)
		v2 = (v2 - pt->normal.y) / pt->normal.z;
	return pattern_slope_wrap(slen * v1 + alen * v2);
}

/* pattern_at without function patterns: what the scene's generated functions
 * call (function_pattern.cl), so that no function calls itself through a
 * pattern, which OpenCL C cannot (eval refuses a function pattern there). */
static float pattern_plain(global const dev_pattern *pt, global const dev_warp *warps, float3 p, float3 n, float3 d)
{
	int kind = pt->kind;
	int generator = pt->noise_generator;
	if (generator < 1 || generator > 3)
		generator = 2;

	/* POV-Ray's Search_For_Turb: the classic turbulence, which is the last warp. */
	global const dev_warp *turb = 0;
	if (pt->warp_count > 0) {
		global const dev_warp *last = &warps[pt->warp_first + pt->warp_count - 1];
		if (last->kind == WARP_TURBULENCE && last->classic)
			turb = last;
	}

	float v;
	switch (kind) {
	/* discrete: the index, no frequency nor wave */
	case PATTERN_BRICK:      return pattern_brick(p, pt->params[0]);
	case PATTERN_CHECKER:    return pattern_checker(p);
	case PATTERN_CUBIC:      return pattern_cubic(p);
	case PATTERN_HEXAGON:    return pattern_hexagon(p);
	case PATTERN_SQUARE:     return pattern_square(p);
	case PATTERN_TRIANGULAR: return pattern_triangular(p);
	case PATTERN_SOLID:
	case PATTERN_FACETS:     return 0.0f;   /* facets: a normal only */

	case PATTERN_AGATE:
		v = pattern_agate(p, turb, pt->params[0].x, generator);
		break;
	case PATTERN_AOI:
		v = acospi(clamp(dot(normalize(n), normalize(d)), -1.0f, 1.0f));
		break;
	case PATTERN_BOXED:
		v = pattern_clip_density(fmax(fabs(p.x), fmax(fabs(p.y), fabs(p.z))));
		break;
	case PATTERN_BOZO:
	case PATTERN_BUMPS:
	case PATTERN_SPOTTED:
		v = pattern_noise(p, generator);
		break;
	case PATTERN_CELLS:
		v = pattern_cells(p);
		break;
	case PATTERN_CRACKLE:
		v = pattern_crackle(p, pt->params[0], pt->params[1], generator);
		break;
	case PATTERN_CYLINDRICAL:
		v = pattern_clip_density(sqrt(p.x * p.x + p.z * p.z));
		break;
	case PATTERN_DENTS:
		v = pattern_noise(p, generator);
		v = v * v * v;
		break;
	case PATTERN_GRADIENT:
		v = pattern_gradient(p, pt->params[0].xyz);
		break;
	case PATTERN_GRANITE:
		v = pattern_granite(p, generator);
		break;
	case PATTERN_LEOPARD:
		v = pattern_leopard(p);
		break;
	case PATTERN_MARBLE:
		v = p.x + (turb ? turb->a.x * pattern_warp_turbulence(turb, generator, p) : 0.0f);
		break;
	case PATTERN_ONION:
		v = fmod(length(p), 1.0f);
		break;
	case PATTERN_PLANAR:
		v = pattern_clip_density(fabs(p.y));
		break;
	case PATTERN_QUILTED:
		v = pattern_quilted(p, pt->params[0].x, pt->params[0].y);
		break;
	case PATTERN_RADIAL:
		v = pattern_radial(p);
		break;
	case PATTERN_RIPPLES:
	case PATTERN_WAVES: {
		int n_waves = pt->params[0].x >= 1.0f ? (int)pt->params[0].x : 10;
		v = pattern_waves(p, kind == PATTERN_RIPPLES, n_waves, pt->frequency, pt->phase);
		break;
	}
	case PATTERN_SPHERICAL:
		v = pattern_clip_density(length(p));
		break;
	case PATTERN_SPIRAL1:
	case PATTERN_SPIRAL2: {
		/* Agate, spiral1 and spiral2 apply their classic turbulence as a
		 * warp and add its value too, as POV-Ray does. */
		float t = turb ? turb->a.x * pattern_warp_turbulence(turb, generator, p) : 0.0f;
		float rad = sqrt(p.x * p.x + p.y * p.y);
		float s = p.z + rad + pt->params[0].x * pattern_spiral_phi(p.x, p.y, rad) / (2.0f * PATTERN_PI) + t;
		v = kind == PATTERN_SPIRAL1 ? s : pattern_triangle_wave(rad) + pattern_triangle_wave(s);
		break;
	}
	case PATTERN_WOOD:
		v = pattern_wood(p, turb);
		break;
	case PATTERN_WRINKLES:
		v = pattern_wrinkles(p, generator);
		break;
	case PATTERN_SLOPE:
		v = pattern_slope(pt, p, n);
		break;
	case PATTERN_TILING:
		v = pattern_tiling(p, (int)pt->params[0].x);
		break;
	case PATTERN_PAVEMENT:
		v = pattern_pavement(p, pt->params[0], pt->params[1]);
		break;
	case PATTERN_MANDEL:
	case PATTERN_JULIA:
	case PATTERN_MAGNET:
		v = pattern_fractal(kind, p, pt->params[0], pt->params[1], pt->frequency);
		break;
	default:
		return 0.0f;
	}
	return pattern_wave(pt, v);
}

/* object (POV-Ray's object_pattern): 1 where p is inside the object, whose
 * own transformations placed it in the pattern's space, else 0, through the
 * wave (its frequency is 0). The object is a CSG record that no BVH holds
 * (lowering's place_object_patterns), asked as a CSG asks a point that is on
 * none of its leaves; none (-1) is inside nowhere, as POV-Ray's open shapes
 * are. Built only for a scene that has one (OBJECT_PATTERNS, lowering's
 * option): the CSG code it reaches costs every cold build a quarter more,
 * and the pattern tests build this file without it. Only here, not in
 * pattern_plain: a leaf's inside test may run the scene's functions, which
 * call pattern_plain, and OpenCL C has no recursion. */
static float pattern_object(const scene_data *sc, global const dev_pattern *pt, float3 p)
{
	bool outside = true;
#ifdef OBJECT_PATTERNS
	int rec = as_int(pt->params[0].x);
	if (rec >= 0)   /* classified as a point on none of its leaves (k -1) */
		csg_classify(sc, sc->nodes, sc->prims, &sc->prims[rec], -1, p, &outside, sc->counts, RAY_SHADOW);
#endif
	return pattern_wave(pt, outside ? 0.0f : 1.0f);
}

/* The value of the pattern pt at p, a point in the pattern's space (pt->rows
 * already applied); n, the unit shading normal, and d, the ray's direction,
 * both in world space, serve only aoi and slope. Continuous patterns give [0, 1] (some,
 * as in POV-Ray, a little beyond: the map clamps); discrete ones (brick,
 * checker, cubic, hexagon, square, triangular) the index of a list entry. */
/* The value of the pattern pt at p, a point already warped
 * (pattern_warp_point): POV-Ray's Evaluate_TPat, which normals call at
 * points around the warped one. n and d as for pattern_value. */
static float pattern_at(const scene_data *sc, global const dev_pattern *pt, float3 p, float3 n, float3 d)
{
	if (pt->kind == PATTERN_OBJECT)
		return pattern_object(sc, pt, p);
	if (pt->kind != PATTERN_FUNCTION)
		return pattern_plain(pt, sc->warps, p, n, d);
	/* POV-Ray wraps values above 1, not those below 0 */
	float v = scene_function_pattern(sc, (int)pt->params[0].x, p);
	if (v > 1.0f)
		v = fmod(v, 1.0f);
	return pattern_wave(pt, v);
}

static float pattern_value(const scene_data *sc, global const dev_pattern *pt, float3 p, float3 n, float3 d)
{
	return pattern_at(sc, pt, pattern_warp_point(pt, sc->warps, p), n, d);
}
