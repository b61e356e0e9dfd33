/* sky_sample.cl: directions drawn from the sky's image by importance, and
 * their density (src/lower_sky.c builds the tables; dev_sky in shared.h).
 *
 *   float pdf;
 *   float3 wi = sky_sample(sc->sky_dist, sc->sky_cdf, u0, u1, u2, u3, &pdf);
 *   ... sky_pdf(sc->sky_dist, sc->sky_cdf, wi) is that pdf again ...
 *
 * A texel is chosen by its row's cdf, then by its column's within the row,
 * and a direction uniformly in the texel's solid angle: uniform in the
 * azimuth and in the sine of the latitude. So the density over the image's
 * directions is constant over a texel, its probability over its solid angle,
 * and both functions compute it from the same float cdfs: the pdf is exactly
 * the density the sampler draws from. The image's space is texture_image's
 * map_type 1 (kernels/texture.cl): azimuth from +x toward +z, the top row at
 * +y; a world direction reaches it through dev_sky.rows. Needs shared.h only,
 * so that tests/test_sky.c can build it alone. */

#define SKY_PI 3.14159265358979f

/* The sines of row r's lowest and highest latitude (r = 0: the top row). */
static inline float sky_row_z(int height, int r, float *z_lo)
{
	float h = (float)height;
	*z_lo = sin(SKY_PI * ((float)(height - 1 - r) / h - 0.5f));
	return sin(SKY_PI * ((float)(height - r) / h - 0.5f));
}

/* The interval of cdf c (n + 1 values from 0 to 1) that holds u in [0, 1):
 * the last i with c[i] <= u, so an interval of zero width is never chosen. */
static inline int sky_search(global const float *c, int n, float u)
{
	int lo = 0, hi = n - 1;
	while (lo < hi) {
		int mid = (lo + hi + 1) / 2;
		if (c[mid] <= u)
			lo = mid;
		else
			hi = mid - 1;
	}
	return lo;
}

/* The density over the image's directions in texel (r, c): its probability
 * over its solid angle. */
static inline float sky_texel_pdf(global const dev_sky *s, global const float *cdf, int r, int c)
{
	int w = s->width, h = s->height;
	global const float *row = cdf + (h + 1) + r * (w + 1);
	float z_lo, z_hi = sky_row_z(h, r, &z_lo);
	float solid = (2.0f * SKY_PI / (float)w) * (z_hi - z_lo);
	float p = (cdf[r + 1] - cdf[r]) * (row[c + 1] - row[c]);
	return solid > 0.0f ? p / solid : 0.0f;
}

/* A world direction drawn by importance from u0..u3 in [0, 1), and its pdf
 * in solid angle. */
static inline float3 sky_sample(global const dev_sky *s, global const float *cdf, float u0, float u1, float u2, float u3,
                         float *pdf)
{
	int w = s->width, h = s->height;
	int r = sky_search(cdf, h, u0);
	int c = sky_search(cdf + (h + 1) + r * (w + 1), w, u1);
	float z_lo, z_hi = sky_row_z(h, r, &z_lo);
	float z = clamp(z_lo + u2 * (z_hi - z_lo), -1.0f, 1.0f), rho = sqrt(fmax(0.0f, 1.0f - z * z));
	float phi = 2.0f * SKY_PI * ((float)c + u3) / (float)w;
	float3 si = (float3)(rho * cos(phi), z, rho * sin(phi));
	float3 d = (float3)(dot(s->inv[0].xyz, si), dot(s->inv[1].xyz, si), dot(s->inv[2].xyz, si));
	float len = length(d);
	/* the Jacobian from the image's directions to the world's: |det rows| / |rows d|^3,
	 * and |rows d| = 1 / len for d = inv si / len */
	*pdf = len > 0.0f ? sky_texel_pdf(s, cdf, r, c) * s->det * len * len * len : 0.0f;
	return len > 0.0f ? d / len : (float3)(0.0f, 1.0f, 0.0f);
}

/* The pdf in solid angle with which sky_sample draws the unit direction d. */
static inline float sky_pdf(global const dev_sky *s, global const float *cdf, float3 d)
{
	float3 q = (float3)(dot(s->rows[0].xyz, d), dot(s->rows[1].xyz, d), dot(s->rows[2].xyz, d));
	float len = length(q);
	if (!(len > 0.0f))
		return 0.0f;
	q /= len;
	int w = s->width, h = s->height;
	float turns = q.x == 0.0f && q.z == 0.0f ? 0.0f : atan2(q.z, q.x) / (2.0f * SKY_PI);
	if (turns < 0.0f)
		turns += 1.0f;
	int c = clamp((int)(turns * (float)w), 0, w - 1);
	float v = 0.5f + asin(clamp(q.y, -1.0f, 1.0f)) / SKY_PI;   /* 1 at the top */
	int r = clamp((int)((1.0f - v) * (float)h), 0, h - 1);
	return sky_texel_pdf(s, cdf, r, c) * s->det / (len * len * len);
}
