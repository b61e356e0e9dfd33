/* image.cl: images on the device, as POV-Ray 3.7 reads them at a point
 * (imageutil.cpp), in float: the point to the image by its map_type
 * (image_pos), the texel or an interpolation of four (image_at). An image_map
 * takes the colour (texture.cl's texture_image), an image_pattern a value
 * (image_value), a bump_map a tilt of the normal (image_bump), a
 * material_map the entry of its map (image_material). The pattern's
 * params[0] say which image and how: x the dev_image, y map_type, z
 * interpolate, w once. A density_file's voxels are an image too, four
 * voxels to a texel (density_file_value).
 *
 * Exported: image_pos, image_at, image_value, image_bump, image_material,
 * density_file_value. */

/* POV-Ray's wrap: v into [0, n). */
static inline float image_wrap(float v, float n)
{
	float t = fmod(v, n);
	if (t < 0.0f)
		t += n;
	return t >= n ? 0.0f : t;
}

/* The angle of (c, z) from +x in the x-z plane, in turns (POV-Ray's theta / 2 pi). */
static inline float image_turns(float c, float z)
{
	float theta = z == 0.0f ? (c > 0.0f ? 0.0f : PATTERN_PI) : acos(clamp(c, -1.0f, 1.0f));
	if (z < 0.0f)
		theta = 2.0f * PATTERN_PI - theta;
	return theta / (2.0f * PATTERN_PI);
}

/* One texel of plane 0 (the colours) or 1 (IMAGE_FILTER's filters): POV-Ray's
 * no_interpolation (once: the nearest edge texel, else wrapped). */
static inline float4 image_texel(const scene_data *sc, global const dev_image *im, int plane, float x, float y,
                                 int once)
{
	int w = im->width, h = im->height;
	int ix = once ? (x < 0.0f ? 0 : x >= (float)w ? w - 1 : (int)x) : (int)image_wrap(x, (float)w);
	int iy = once ? (y < 0.0f ? 0 : y >= (float)h ? h - 1 : (int)y) : (int)image_wrap(y, (float)h);
	return sc->texels[im->first + plane * w * h + clamp(iy, 0, h - 1) * w + clamp(ix, 0, w - 1)];
}

/* Where p (the pattern's space, warped) falls on pt's image, in texels, x to
 * the right and y down from the top row (POV-Ray's map_pos); false off a once
 * image, or where the map_type has no point. */
static bool image_pos(const scene_data *sc, global const dev_pattern *pt, float3 p, float *x, float *y)
{
	global const dev_image *im = &sc->images[(int)pt->params[0].x];
	int type = (int)pt->params[0].y, once = pt->params[0].w != 0.0f;
	float w = (float)im->width, h = (float)im->height, u, v;
	float len = length(p), len_xz = sqrt(p.x * p.x + p.z * p.z);
	if (type == 0) {          /* planar: x, y in [0, 1] */
		if (once && (p.x < 0.0f || p.x > 1.0f || p.y < 0.0f || p.y > 1.0f))
			return false;
		u = fmod(p.x * w, w);
		v = fmod(p.y * h, h);
	} else if (type == 1) {   /* spherical */
		if (len == 0.0f)
			return false;
		u = (len_xz == 0.0f ? 0.0f : image_turns(p.x / len_xz, p.z)) * w;
		v = (0.5f + asin(clamp(p.y / len, -1.0f, 1.0f)) / PATTERN_PI) * h;
	} else if (type == 2) {   /* cylindrical: y in [0, 1] */
		if (once && (p.y < 0.0f || p.y > 1.0f))
			return false;
		if (len == 0.0f || len_xz == 0.0f)
			return false;
		v = fmod(p.y * h, h);
		u = image_turns(p.x / len_xz, p.z) * w;
	} else {                  /* torus, major radius 1 */
		if (len_xz == 0.0f)
			return false;
		float theta = -image_turns(p.x / len_xz, p.z);
		float x = len_xz - 1.0f, r = sqrt(x * x + p.y * p.y);
		float phi = acos(clamp(-x / r, -1.0f, 1.0f));
		if (p.y > 0.0f)
			phi = 2.0f * PATTERN_PI - phi;
		u = -theta * w;
		v = phi / (2.0f * PATTERN_PI) * h;
	}
	/* POV-Ray adds 1e-10 texels, which in double puts a point that rounding
	 * left a hair before an edge of the image (a box's face at 0) after it;
	 * float's rounding needs 2e-6 of the image */
	u += 2e-6f * w;
	v += 2e-6f * h;
	if (once && (u >= w || v >= h || u < 0.0f || v < 0.0f))
		return false;
	*x = image_wrap(u, w);
	*y = image_wrap(-v, h);   /* the image's rows go down */
	return true;
}

/* POV-Ray's bicubic weights (Catmull-Rom) of the four texels about a point p
 * of the way from the second to the third. */
static inline float4 image_cubic(float p)
{
	float q = 1.0f - p;
	return (float4)(-0.5f * p * q * q, 0.5f * q * (q * (3.0f * p + 1.0f) + 1.0f),
	                0.5f * p * (p * (3.0f * q + 1.0f) + 1.0f), -0.5f * q * p * p);
}

/* The colour (plane 0) or the filter (plane 1) at texel position (x, y): the
 * texel, or POV-Ray's interpolation of four (2 bilinear, 4 normalized
 * distance) or sixteen (3 bicubic), unmultiplied by alpha where the image is
 * premultiplied. */
static float4 image_at_plane(const scene_data *sc, global const dev_pattern *pt, float x, float y, int plane)
{
	global const dev_image *im = &sc->images[(int)pt->params[0].x];
	int interp = (int)pt->params[0].z, once = pt->params[0].w != 0.0f;
	float4 c;
	if (interp == 0) {
		c = image_texel(sc, im, plane, x, y, once);
	} else if (interp == 3) {
		x += 0.5f;
		y += 0.5f;
		float fx = floor(x), fy = floor(y);
		float4 wx = image_cubic(x - fx), wy = image_cubic(y - fy);
		float cx[4] = { wx.x, wx.y, wx.z, wx.w }, cy[4] = { wy.x, wy.y, wy.z, wy.w };
		c = (float4)(0.0f);
		for (int j = 0; j < 4; j++)
			for (int i = 0; i < 4; i++)
				c += cx[i] * cy[j] * image_texel(sc, im, plane, fx + (float)(i - 2), fy + (float)(j - 2), once);
	} else {
		x += 0.5f;
		y += 0.5f;
		float fx = floor(x), fy = floor(y), a = x - fx, b = y - fy, f[4];
		if (interp == 2) {        /* bilinear */
			f[0] = a * b;
			f[1] = (1.0f - a) * b;
			f[2] = a * (1.0f - b);
			f[3] = (1.0f - a) * (1.0f - b);
		} else {                  /* normalized distance */
			f[0] = 1.0f / ((1.0f - a) * (1.0f - a) + (1.0f - b) * (1.0f - b));
			f[1] = 1.0f / (a * a + (1.0f - b) * (1.0f - b));
			f[2] = 1.0f / ((1.0f - a) * (1.0f - a) + b * b);
			f[3] = 1.0f / (a * a + b * b);
			float sum = f[0] + f[1] + f[2] + f[3];
			for (int k = 0; k < 4; k++)
				f[k] = isinf(sum) ? (isinf(f[k]) ? 1.0f : 0.0f) : f[k] / sum;
		}
		c = f[0] * image_texel(sc, im, plane, fx, fy, once) + f[1] * image_texel(sc, im, plane, fx - 1.0f, fy, once) +
		    f[2] * image_texel(sc, im, plane, fx, fy - 1.0f, once) +
		    f[3] * image_texel(sc, im, plane, fx - 1.0f, fy - 1.0f, once);
	}
	if (plane == 0 && (im->flags & IMAGE_PREMULTIPLIED) && c.w > 1e-10f)
		c.xyz /= c.w;
	return c;
}

static inline float4 image_at(const scene_data *sc, global const dev_pattern *pt, float x, float y)
{
	return image_at_plane(sc, pt, x, y, 0);
}

/* POV-Ray's grey of a colour. */
static inline float image_grey(float4 c)
{
	return 0.297f * c.x + 0.589f * c.y + 0.114f * c.z;
}

/* image_pattern's value at p (warped): the grey of the colour there, or with
 * use_alpha (params[1].x) its transparency (its red without an alpha
 * channel: params[1].y 0), in [0, 1]; 0 off a once image. */
static float image_value(const scene_data *sc, global const dev_pattern *pt, float3 p)
{
	float x, y;
	if (!image_pos(sc, pt, p, &x, &y))
		return 0.0f;
	float4 c = image_at(sc, pt, x, y);
	float v = pt->params[1].x == 0.0f ? image_grey(c) : pt->params[1].y != 0.0f ? 1.0f - c.w : c.x;
	return clamp(v, 0.0f, 1.0f);
}

/* A bump_map at t (warped) tilts n (in the pattern's space): POV-Ray's
 * bump_map takes the greys at the texel and at its neighbours down-left and
 * down-right as heights times the bump_size, and sets n to the normal of the
 * triangle they make, in a frame around n. Off a once image, n unchanged. */
static float3 image_bump(const scene_data *sc, global const dev_pattern *pt, float3 t, float3 n)
{
	global const dev_image *im = &sc->images[(int)pt->params[0].x];
	float x, y, w = (float)im->width, h = (float)im->height, amount = pt->bump_size;
	if (!image_pos(sc, pt, t, &x, &y))
		return n;
	float h1 = amount * image_grey(image_at(sc, pt, x, y));
	x -= 1.0f;
	y += 1.0f;
	x = x < 0.0f ? x + w : x >= w ? x - w : x;
	y = y < 0.0f ? y + h : y >= h ? y - h : y;
	float h2 = amount * image_grey(image_at(sc, pt, x, y));
	x += 2.0f;
	x = x < 0.0f ? x + w : x >= w ? x - w : x;
	float h3 = amount * image_grey(image_at(sc, pt, x, y));
	float3 p1 = (float3)(0.0f, h1, 0.0f), p2 = (float3)(-1.0f, h2, 1.0f), p3 = (float3)(1.0f, h3, 1.0f);
	float3 b = normalize(cross(p3 - p2, p1 - p2));
	float3 yp = n, xp = cross(yp, (float3)(0.0f, 1.0f, 0.0f));
	float len = length(xp);
	if (len < 1e-10f) {   /* n along y */
		yp = (float3)(0.0f, fabs(n.y - 1.0f) < 1e-10f ? 1.0f : -1.0f, 0.0f);
		xp = (float3)(1.0f, 0.0f, 0.0f);
		len = 1.0f;
	}
	xp /= len;
	float3 zp = normalize(cross(xp, yp));
	return xp * b.x + yp * b.y - zp * b.z;
}

/* material_map's entry at p (warped): the material number there (the texels'
 * x: palette indices, or red * 255), folded into the textures as POV-Ray's
 * material_map does (a number past the count taken modulo it, the count itself
 * the last); 0 off a once image. */
static float image_material(const scene_data *sc, global const dev_pattern *pt, float3 p)
{
	float x, y;
	if (!image_pos(sc, pt, p, &x, &y))
		return 0.0f;
	float n = floor(image_at(sc, pt, x, y).x), count = (float)pt->map_count;
	if (n > count)
		n = fmod(n, count);
	return fmin(n, count - 1.0f);
}

/* ---- density_file: a df3 file's voxels (src/eval_df3.c) ----
 * params[0].x the dev_image, yzw the sizes nx, ny, nz; params[1].x the
 * interpolation: 0 nearest, 1 trilinear, 2 tricubic. Voxel x + nx (y + ny z)
 * is component i % 4 of texel i / 4. */

static inline float df3_voxel(const scene_data *sc, int first, int nx, int ny, int x, int y, int z)
{
	int i = (z * ny + y) * nx + x;
	float4 t = sc->texels[first + (i >> 2)];
	int k = i & 3;
	return k == 0 ? t.x : k == 1 ? t.y : k == 2 ? t.z : t.w;
}

/* POV-Ray's neighbour of a voxel for the tricubic: i + 1, i + 2 wrap around;
 * i - 1 below 0 is POV-Ray's unsigned -1 taken modulo n (its size_t test for
 * a negative index never holds), which we follow to give its pixels. */
static inline int df3_wrap(int i, int n)
{
	return i < 0 ? (int)(0xFFFFFFFFFFFFFFFFUL % (ulong)n) : i % n;
}

/* POV-Ray's cubic through fa, fb, fc, fd at t in [0, 1] between fb and fc. */
static inline float df3_cubic(float t, float fa, float fb, float fc, float fd)
{
	float b = (fc - fa) * 0.5f, d = (fd - fb) * 0.5f;
	float e = 2.0f * (fb - fc) + b + d, f = -3.0f * (fb - fc) - 2.0f * b - d;
	return ((e * t + f) * t + b) * t + fb;
}

/* The density at p (warped): the unit cube holds the voxels, 0 outside it. */
static float density_file_value(const scene_data *sc, global const dev_pattern *pt, float3 p)
{
	if (!(p.x >= 0.0f && p.x < 1.0f && p.y >= 0.0f && p.y < 1.0f && p.z >= 0.0f && p.z < 1.0f))
		return 0.0f;
	int first = sc->images[(int)pt->params[0].x].first;
	int nx = (int)pt->params[0].y, ny = (int)pt->params[0].z, nz = (int)pt->params[0].w;
	int mode = (int)pt->params[1].x;
	float xx = p.x * (float)nx, yy = p.y * (float)ny, zz = p.z * (float)nz;
	/* a point a hair below 1 can round to the size: the last voxel */
	int x1 = min((int)xx, nx - 1), y1 = min((int)yy, ny - 1), z1 = min((int)zz, nz - 1);
	if (mode == 0)
		return df3_voxel(sc, first, nx, ny, x1, y1, z1);
	float a = xx - floor(xx), b = yy - floor(yy), c = zz - floor(zz), v;
	if (mode == 1) {   /* trilinear, the far neighbours wrapped as POV-Ray does */
		int x2 = (x1 + 1) % nx, y2 = (y1 + 1) % ny, z2 = (z1 + 1) % nz;
		float f111 = df3_voxel(sc, first, nx, ny, x1, y1, z1), f112 = df3_voxel(sc, first, nx, ny, x2, y1, z1);
		float f121 = df3_voxel(sc, first, nx, ny, x1, y2, z1), f122 = df3_voxel(sc, first, nx, ny, x2, y2, z1);
		float f211 = df3_voxel(sc, first, nx, ny, x1, y1, z2), f212 = df3_voxel(sc, first, nx, ny, x2, y1, z2);
		float f221 = df3_voxel(sc, first, nx, ny, x1, y2, z2), f222 = df3_voxel(sc, first, nx, ny, x2, y2, z2);
		v = ((f111 * (1.0f - a) + f112 * a) * (1.0f - b) + (f121 * (1.0f - a) + f122 * a) * b) * (1.0f - c) +
		    ((f211 * (1.0f - a) + f212 * a) * (1.0f - b) + (f221 * (1.0f - a) + f222 * a) * b) * c;
	} else {           /* tricubic: along z, then y, then x */
		int k0 = df3_wrap(z1 - 1, nz), k1 = df3_wrap(z1, nz), k2 = df3_wrap(z1 + 1, nz), k3 = df3_wrap(z1 + 2, nz);
		float row[4];
		for (int i = 0; i < 4; i++) {
			int ii = df3_wrap(x1 + i - 1, nx);
			float col[4];
			for (int j = 0; j < 4; j++) {
				int jj = df3_wrap(y1 + j - 1, ny);
				col[j] = df3_cubic(c, df3_voxel(sc, first, nx, ny, ii, jj, k0), df3_voxel(sc, first, nx, ny, ii, jj, k1),
				                   df3_voxel(sc, first, nx, ny, ii, jj, k2), df3_voxel(sc, first, nx, ny, ii, jj, k3));
			}
			row[i] = df3_cubic(b, col[0], col[1], col[2], col[3]);
		}
		v = df3_cubic(a, row[0], row[1], row[2], row[3]);
	}
	return fmax(v, 0.0f);
}
