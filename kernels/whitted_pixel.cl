/* whitted_pixel.cl: POV-Ray 3.7's anti-aliasing and focal blur for the
 * Whitted integrator, as its TraceTask and TracePixel sample a pixel.
 *
 * A "trace" is POV-Ray's TracePixel::operator()(x, y): the colour and
 * transmittance at the image point (x, y) in its pixel coordinates, where
 * (x, y) integer is a pixel's centre; with focal blur it is many rays through
 * the lens, stopped by a confidence test. +A (src/render_aa.c) runs two passes:
 * whitted_aa_grid traces one point per pixel (+AM1: the centres, with the row
 * above and the column left of the image; +AM2: the corners) into a scratch
 * buffer, then whitted_aa_m1 (one work item per 32x32 block, since POV-Ray's
 * method 1 decides each pixel from its left and top neighbours as they stand
 * after their own supersampling) or whitted_aa_m2 (one work item per pixel)
 * supersamples and writes the film. Every sample place and its jitter come
 * from POV-Ray's tables (pattern_hash is its hashTable), so a pixel's samples
 * are POV-Ray's. */

#define WHITTED_AA_BLOCK 32       /* POV-Ray's default Render_Block_Size: method 1 starts each block afresh */
#define WHITTED_AA_STACK 32       /* method 2's squares waiting: 3 per level, +R9 at most */
#define WHITTED_SUBPIXEL_GRID 16  /* focal blur's sub-pixel grid (SUB_PIXEL_GRID_SIZE) */
#define WHITTED_LENS_HEADER 3     /* float4s before the lens samples in camera_rays (src/lower_camera_lens.c) */

/* POV-Ray's JitterTable. */
constant float whitted_jitter_table[256] = {
	-0.500000f, 0.005890f, 0.011749f, -0.490234f, 0.023468f, -0.470703f, -0.480469f, 0.017609f,
	0.046906f, -0.447266f, -0.441406f, 0.056671f, -0.460938f, 0.044952f, 0.035187f, -0.466797f,
	0.093781f, -0.400391f, -0.394531f, 0.103546f, -0.382813f, 0.123077f, 0.113312f, -0.388672f,
	-0.421875f, 0.084015f, 0.089874f, -0.412109f, 0.070343f, -0.423828f, -0.433594f, 0.064484f,
	0.187531f, -0.306641f, -0.300781f, 0.197296f, -0.289063f, 0.216827f, 0.207062f, -0.294922f,
	-0.265625f, 0.240265f, 0.246124f, -0.255859f, 0.226593f, -0.267578f, -0.277344f, 0.220734f,
	-0.343750f, 0.162140f, 0.167999f, -0.333984f, 0.179718f, -0.314453f, -0.324219f, 0.173859f,
	0.140656f, -0.353516f, -0.347656f, 0.150421f, -0.367188f, 0.138702f, 0.128937f, -0.373047f,
	0.375031f, -0.119141f, -0.113281f, 0.384796f, -0.101563f, 0.404327f, 0.394562f, -0.107422f,
	-0.078125f, 0.427765f, 0.433624f, -0.068359f, 0.414093f, -0.080078f, -0.089844f, 0.408234f,
	-0.031250f, 0.474640f, 0.480499f, -0.021484f, 0.492218f, -0.001953f, -0.011719f, 0.486359f,
	0.453156f, -0.041016f, -0.035156f, 0.462921f, -0.054688f, 0.451202f, 0.441437f, -0.060547f,
	-0.187500f, 0.318390f, 0.324249f, -0.177734f, 0.335968f, -0.158203f, -0.167969f, 0.330109f,
	0.359406f, -0.134766f, -0.128906f, 0.369171f, -0.148438f, 0.357452f, 0.347687f, -0.154297f,
	0.281281f, -0.212891f, -0.207031f, 0.291046f, -0.195313f, 0.310577f, 0.300812f, -0.201172f,
	-0.234375f, 0.271515f, 0.277374f, -0.224609f, 0.257843f, -0.236328f, -0.246094f, 0.251984f,
	-0.249969f, 0.255859f, 0.261719f, -0.240204f, 0.273438f, -0.220673f, -0.230438f, 0.267578f,
	0.296875f, -0.197235f, -0.191376f, 0.306641f, -0.210907f, 0.294922f, 0.285156f, -0.216766f,
	0.343750f, -0.150360f, -0.144501f, 0.353516f, -0.132782f, 0.373047f, 0.363281f, -0.138641f,
	-0.171844f, 0.333984f, 0.339844f, -0.162079f, 0.320313f, -0.173798f, -0.183563f, 0.314453f,
	0.437500f, -0.056610f, -0.050751f, 0.447266f, -0.039032f, 0.466797f, 0.457031f, -0.044891f,
	-0.015594f, 0.490234f, 0.496094f, -0.005829f, 0.476563f, -0.017548f, -0.027313f, 0.470703f,
	-0.093719f, 0.412109f, 0.417969f, -0.083954f, 0.429688f, -0.064423f, -0.074188f, 0.423828f,
	0.390625f, -0.103485f, -0.097626f, 0.400391f, -0.117157f, 0.388672f, 0.378906f, -0.123016f,
	0.125000f, -0.369110f, -0.363251f, 0.134766f, -0.351532f, 0.154297f, 0.144531f, -0.357391f,
	-0.328094f, 0.177734f, 0.183594f, -0.318329f, 0.164063f, -0.330048f, -0.339813f, 0.158203f,
	-0.281219f, 0.224609f, 0.230469f, -0.271454f, 0.242188f, -0.251923f, -0.261688f, 0.236328f,
	0.203125f, -0.290985f, -0.285126f, 0.212891f, -0.304657f, 0.201172f, 0.191406f, -0.310516f,
	-0.437469f, 0.068359f, 0.074219f, -0.427704f, 0.085938f, -0.408173f, -0.417938f, 0.080078f,
	0.109375f, -0.384735f, -0.378876f, 0.119141f, -0.398407f, 0.107422f, 0.097656f, -0.404266f,
	0.031250f, -0.462860f, -0.457001f, 0.041016f, -0.445282f, 0.060547f, 0.050781f, -0.451141f,
	-0.484344f, 0.021484f, 0.027344f, -0.474579f, 0.007813f, -0.486298f, -0.496063f, 0.001953f,
};

/* POV-Ray's Jitter2d(DBL x, DBL y): an offset in [-0.5, 0.5) for each place,
 * always the same for the same place. */
static inline float2 whitted_jitter(real x, real y)
{
	int ax = (int)(x * (real)1021), ay = (int)(y * (real)1019), bx = (int)(x * (real)1019), by = (int)(y * (real)1021);
	return (float2)(whitted_jitter_table[pattern_hash[(pattern_hash[ax & 0xfff] ^ ay) & 0xfff] & 0xff],
	                whitted_jitter_table[pattern_hash[(pattern_hash[bx & 0xfff] ^ by) & 0xfff] & 0xff]);
}

/* The camera's ray ray_number at POV-Ray's pixel coordinates (x, y): false
 * where the camera makes none. Focal blur moves the ray's origin across the
 * lens as POV-Ray's JitterCameraRay does, by the lens sample ray_number and a
 * jitter of the point (camera_rays holds the lens, src/lower_camera_lens.c). */
static inline bool whitted_camera(const scene_data *sc, real x, real y, int ray_number, float3 *o, float3 *d)
{
	global const dev_params *p = sc->p;
	real ix = x + (real)0.5, iy = y + (real)0.5;   /* from the image's top left corner */
	if ((int)p->lens.z == CAMERA_MESH) {   /* a face a pixel: the pixel the point is in */
		int px = clamp((int)floor(ix), 0, p->width - 1), py = clamp((int)floor(iy), 0, p->height - 1);
		int rays = max((int)p->lens.w, 1);
		float2 xy;
		if (!camera_view(sc, px, py, ((float)ray_number + 0.5f) / (float)rays, 0.5f, o, d, &xy))
			return false;
		*d = camera_perturb(sc, xy, normalize(*d));
		return true;
	}
	int px = (int)floor(ix), py = (int)floor(iy);
	float2 xy;
	if (!camera_ray(p, px, py, (float)(ix - (real)px), (float)(iy - (real)py), o, d, &xy))
		return false;
	if (p->lens.x > 0.0f) {
		global const float4 *lens = sc->camera_rays;
		float4 xperp = lens[0], yperp = lens[1], s = lens[WHITTED_LENS_HEADER + ray_number];
		/* POV-Ray jitters at its own coordinates, moved to the pixel's centre */
		float2 j = whitted_jitter(x + (real)0.5, y - (real)0.5) * (2.0f * yperp.w);
		float r = 0.5f * p->lens.x;
		float3 defl = (r * (s.x + j.x)) * xperp.xyz - (r * (s.y + j.y)) * yperp.xyz;
		*o += defl;
		*d = *d * xperp.w - defl;
	}
	*d = camera_perturb(sc, xy, normalize(*d));
	return true;
}

/* One camera ray's colour and transmittance. */
static inline float4 whitted_camera_colour(const scene_data *sc, float3 o, float3 d, media_stack around, first_hit *first)
{
	global const dev_params *p = sc->p;
	whitted_ray camera = whitted_child(o, d, (float3)(1.0f), 1.0f, 1.0f, 0, WRAY_IMAGE, p->camera_solids, around);
	sc->counts[COUNT_RAYS + RAY_CAMERA]++;
	float transm = 0.0f;
	float3 l = film_finite(whitted_radiance(sc, camera, first, &transm));
	return (float4)(l, transm);
}

/* Focal blur at (x, y) (TraceRayWithFocalBlur): rays through the lens's
 * samples in batches, each at a sub-pixel place of a 16 x 16 grid picked by
 * POV-Ray's hash, until after a batch the variance of the mean of every
 * channel is under the threshold for that many samples (or all were taken). */
static inline float4 whitted_focal(const scene_data *sc, real x, real y, media_stack around, first_hit *first)
{
	global const float4 *lens = sc->camera_rays;
	int n = (int)lens[2].x, least = (int)lens[2].y;
	int seed = (int)(x * (real)313 + (real)11) + (int)(y * (real)311 + (real)17);
	float4 sum = (float4)(0.0f), s1 = (float4)(0.0f), s2 = (float4)(0.0f);
	int nr = 0;
	while (nr < n) {
		int dxi = pattern_hash[(seed + nr) & 0xfff] % WHITTED_SUBPIXEL_GRID;
		int dyi = pattern_hash[(seed + nr + 1) & 0xfff] % WHITTED_SUBPIXEL_GRID;
		real dx = (real)(2 * dxi + 1) / (real)(2 * WHITTED_SUBPIXEL_GRID) - (real)0.5;
		real dy = (real)(2 * dyi + 1) / (real)(2 * WHITTED_SUBPIXEL_GRID) - (real)0.5;
		float2 j = whitted_jitter(dx, dy);
		dx += (real)((j.x - 0.5f) / (float)WHITTED_SUBPIXEL_GRID);
		dy += (real)((j.y - 0.5f) / (float)WHITTED_SUBPIXEL_GRID);
		float3 o, d;
		float4 c = (float4)(0.0f, 0.0f, 0.0f, 1.0f);
		if (whitted_camera(sc, x + dx, y + dy, nr, &o, &d)) {
			c = whitted_camera_colour(sc, o, d, around, first);
			sum += c;
		}
		s1 += c;
		s2 += c * c;
		float4 s = lens[WHITTED_LENS_HEADER + nr++];
		if (s.w != 0.0f && nr >= least) {   /* the end of a batch: the confidence test */
			float k = (float)nr;
			float4 v = (s2 / k - (s1 / k) * (s1 / k)) / k;
			if (all(v < (float4)(s.z)))
				break;
		}
	}
	return sum / (float)nr;
}

/* POV-Ray's trace of the point (x, y): focal blur, or the camera's rays there
 * (a mesh_camera may have several) averaged; where it makes none, black and
 * transparent. */
static inline float4 whitted_trace(const scene_data *sc, real x, real y, media_stack around, first_hit *first)
{
	global const dev_params *p = sc->p;
	if (p->lens.x > 0.0f)
		return whitted_focal(sc, x, y, around, first);
	int rays = (int)p->lens.z == CAMERA_MESH ? max((int)p->lens.w, 1) : 1, traced = 0;
	float4 sum = (float4)(0.0f);
	for (int r = 0; r < rays; r++) {
		float3 o, d;
		if (whitted_camera(sc, x, y, r, &o, &d)) {
			sum += whitted_camera_colour(sc, o, d, around, first);
			traced++;
		}
	}
	return traced ? sum / (float)traced : (float4)(0.0f, 0.0f, 0.0f, 1.0f);
}

/* POV-Ray's Colour_Distance_RGBT of two colours after its anti-aliasing gamma
 * (aa.w: the exponent from the scene's working gamma through +AG's). */
static inline float whitted_aa_distance(float4 a, float4 b, float gexp)
{
	float3 ga = pow(fmax(a.xyz, (float3)(0.0f)), (float3)(gexp)), gb = pow(fmax(b.xyz, (float3)(0.0f)), (float3)(gexp));
	float3 d = fabs(ga - gb);
	return d.x + d.y + d.z + fabs(a.w - b.w);
}

static inline void whitted_aa_write(const scene_data *sc, global long4 *film, global float4 *aov, int pixel, float4 c)
{
	film[pixel] += film_fixed(c.xyz, 0);
	if (sc->p->aov)
		film_add_transm(aov, pixel, c.w);
}

/* The first pass: one trace per point of a (width + 1) x (rows + 1) grid. For
 * method 1, point (i, j) is the centre of pixel (i - 1, first_row + j - 1):
 * the image's pixels with the row above and the column left of it, which
 * POV-Ray traces for the first blocks; for method 2, the top left corner of
 * pixel (i, first_row + j). Each image pixel's AOVs come from its point. */
#if !defined(KERNELS_SOME) || defined(KERNELS_WHITTED_AA1) || defined(KERNELS_WHITTED_AA2)   /* lower_kernel_options: the kernels a render launches */
kernel void whitted_aa_grid(SCENE_BUFFERS(SCENE_PARAM) global const dev_params *p, global long4 *film,
                            global uint *counters, global float4 *aov, global float4 *grid, int first_row, int rows,
                            int method)
{
	int g = get_global_id(0), w1 = p->width + 1;
	if (g >= w1 * (rows + 1))
		return;
	uint counts[COUNT_N] = { 0 };
	scene_data sc = { SCENE_BUFFERS(SCENE_FIELD) p, counts };
	int i = g % w1, j = g / w1;
	real x = method == 1 ? (real)(i - 1) : (real)i - (real)0.5;
	real y = method == 1 ? (real)(first_row + j - 1) : (real)(first_row + j) - (real)0.5;
	first_hit first = { (float3)(0.0f), (float3)(0.0f), 0.0f, -1 };
	grid[g] = whitted_trace(&sc, x, y, media_around(&sc, p->cam_location.xyz), &first);
	int px = method == 1 ? i - 1 : i, py = first_row + (method == 1 ? j - 1 : j);
	if (p->aov && px >= 0 && px < p->width && py >= first_row && py < first_row + rows)
		film_add_aov(aov, py * p->width + px, &first, 0);
	film_add_counts(counters, counts);
}
#endif

/* POV-Ray's SupersampleOnePixel: the pixel's colour and depth x depth more
 * traces on a grid across it, each jittered, averaged. */
static inline float4 whitted_aa_supersample(const scene_data *sc, real x, real y, float4 col, float4 aa, media_stack around)
{
	int depth = (int)aa.y;
	real step = (real)1 / (real)depth, range = (real)0.5 - step * (real)0.5;
	first_hit none = { (float3)(0.0f), (float3)(0.0f), 0.0f, 0 };
	for (real yy = -range; yy <= range + (real)1e-10; yy += step)
		for (real xx = -range; xx <= range + (real)1e-10; xx += step) {
			real sx = x + xx, sy = y + yy;
			if (aa.z > 0.0f) {
				float2 j = whitted_jitter(sx, sy);
				sx += (real)(j.x * aa.z);
				sy += (real)(j.y * aa.z);
			}
			col += whitted_trace(sc, sx, sy, around, &none);
		}
	return col / (float)(depth * depth + 1);
}

/* Method 1 over one block (NonAdaptiveSupersamplingM1): in raster order, a
 * pixel that differs from its left or top neighbour (as they stand now) by
 * the threshold is supersampled, and so is that neighbour unless it was
 * already; the neighbours outside the block keep their single trace and are
 * never supersampled. scratch holds the block's colours and flags. */
#if !defined(KERNELS_SOME) || defined(KERNELS_WHITTED_AA1)   /* lower_kernel_options: the kernels a render launches */
kernel void whitted_aa_m1(SCENE_BUFFERS(SCENE_PARAM) global const dev_params *p, global long4 *film,
                          global uint *counters, global float4 *aov, global float4 *grid, int first_row, int rows,
                          float4 aa)
{
	int bw = (p->width + WHITTED_AA_BLOCK - 1) / WHITTED_AA_BLOCK, bh = (rows + WHITTED_AA_BLOCK - 1) / WHITTED_AA_BLOCK;
	int b = get_global_id(0);
	if (b >= bw * bh)
		return;
	uint counts[COUNT_N] = { 0 };
	scene_data sc = { SCENE_BUFFERS(SCENE_FIELD) p, counts };
	media_stack around = media_around(&sc, p->cam_location.xyz);
	int w1 = p->width + 1;
	global float4 *cur = grid + w1 * (rows + 1);   /* rows x width: each pixel's colour now, then its flag */
	global float4 *flag = cur + (size_t)rows * p->width;
	int left = b % bw * WHITTED_AA_BLOCK, top = b / bw * WHITTED_AA_BLOCK;
	int right = min(left + WHITTED_AA_BLOCK, p->width) - 1, bottom = min(top + WHITTED_AA_BLOCK, rows) - 1;
	for (int y = top; y <= bottom; y++)
		for (int x = left; x <= right; x++) {
			int k = y * p->width + x;
			real px = (real)x, py = (real)(first_row + y);
			float4 c = grid[(y + 1) * w1 + x + 1];
			bool lframe = x == left, tframe = y == top;
			float4 lc = lframe ? grid[(y + 1) * w1 + x] : cur[k - 1];
			float4 tc = tframe ? grid[y * w1 + x + 1] : cur[k - p->width];
			bool ldiff = whitted_aa_distance(lc, c, aa.w) >= aa.x, tdiff = whitted_aa_distance(tc, c, aa.w) >= aa.x;
			if (ldiff && !lframe && flag[k - 1].x == 0.0f) {
				cur[k - 1] = whitted_aa_supersample(&sc, px - (real)1, py, lc, aa, around);
				flag[k - 1].x = 1.0f;
			}
			if (tdiff && !tframe && flag[k - p->width].x == 0.0f) {
				cur[k - p->width] = whitted_aa_supersample(&sc, px, py - (real)1, tc, aa, around);
				flag[k - p->width].x = 1.0f;
			}
			bool now = ldiff || tdiff;
			cur[k] = now ? whitted_aa_supersample(&sc, px, py, c, aa, around) : c;
			flag[k].x = now ? 1.0f : 0.0f;
		}
	for (int y = top; y <= bottom; y++)
		for (int x = left; x <= right; x++)
			whitted_aa_write(&sc, film, aov, (first_row + y) * p->width + x, cur[y * p->width + x]);
	film_add_counts(counters, counts);
}
#endif

/* A square of method 2's subdivision: its centre and half side in POV-Ray's
 * pixel coordinates, the levels it may still be cut, its corners' colours
 * (top left, bottom left, top right, bottom right) and its share of the pixel. */
typedef struct {
	real x, y, d;
	int level;
	float4 c00, c02, c20, c22;
	float weight;
} whitted_square;

static inline float4 whitted_aa_point(const scene_data *sc, real x, real y, float4 aa, media_stack around)
{
	first_hit none = { (float3)(0.0f), (float3)(0.0f), 0.0f, 0 };
	if (aa.z > 0.0f) {
		float2 j = whitted_jitter(x, y);
		x += (real)(j.x * aa.z);
		y += (real)(j.y * aa.z);
	}
	return whitted_trace(sc, x, y, around, &none);
}

/* Method 2 for one pixel (SubdivideOnePixel): a square whose corners differ
 * by the threshold is cut in four, down to +R levels, its new points traced
 * with jitter; an uncut square is the mean of its corners. A point two
 * squares share is traced by each, at the same place with the same jitter, so
 * it is the colour POV-Ray keeps in its buffer. */
#if !defined(KERNELS_SOME) || defined(KERNELS_WHITTED_AA2)   /* lower_kernel_options: the kernels a render launches */
kernel void whitted_aa_m2(SCENE_BUFFERS(SCENE_PARAM) global const dev_params *p, global long4 *film,
                          global uint *counters, global float4 *aov, global float4 *grid, int first_row, int rows,
                          float4 aa)
{
	int k = get_global_id(0);
	if (k >= p->width * rows)
		return;
	uint counts[COUNT_N] = { 0 };
	scene_data sc = { SCENE_BUFFERS(SCENE_FIELD) p, counts };
	media_stack around = media_around(&sc, p->cam_location.xyz);
	int x = k % p->width, y = k / p->width, w1 = p->width + 1;
	whitted_square stack[WHITTED_AA_STACK];
	int sp = 0;
	stack[sp++] = (whitted_square){ (real)x, (real)(first_row + y), (real)0.5, (int)aa.y - 1, grid[y * w1 + x],
	                                grid[(y + 1) * w1 + x], grid[y * w1 + x + 1], grid[(y + 1) * w1 + x + 1], 1.0f };
	float4 sum = (float4)(0.0f);
	while (sp > 0) {
		whitted_square s = stack[--sp];
		float t = aa.x, g = aa.w;
		bool cut = s.level > 0 && sp + 4 <= WHITTED_AA_STACK &&
		           (whitted_aa_distance(s.c00, s.c02, g) >= t || whitted_aa_distance(s.c00, s.c20, g) >= t ||
		            whitted_aa_distance(s.c00, s.c22, g) >= t || whitted_aa_distance(s.c02, s.c20, g) >= t ||
		            whitted_aa_distance(s.c02, s.c22, g) >= t || whitted_aa_distance(s.c20, s.c22, g) >= t);
		if (!cut) {
			sum += s.weight * 0.25f * (s.c00 + s.c02 + s.c20 + s.c22);
			continue;
		}
		float4 l = whitted_aa_point(&sc, s.x - s.d, s.y, aa, around);   /* the left edge's middle */
		float4 u = whitted_aa_point(&sc, s.x, s.y - s.d, aa, around);   /* the top edge's */
		float4 r = whitted_aa_point(&sc, s.x + s.d, s.y, aa, around);
		float4 b = whitted_aa_point(&sc, s.x, s.y + s.d, aa, around);
		float4 m = whitted_aa_point(&sc, s.x, s.y, aa, around);
		real h = s.d * (real)0.5;
		float w = 0.25f * s.weight;
		stack[sp++] = (whitted_square){ s.x - h, s.y - h, h, s.level - 1, s.c00, l, u, m, w };
		stack[sp++] = (whitted_square){ s.x - h, s.y + h, h, s.level - 1, l, s.c02, m, b, w };
		stack[sp++] = (whitted_square){ s.x + h, s.y - h, h, s.level - 1, u, m, s.c20, r, w };
		stack[sp++] = (whitted_square){ s.x + h, s.y + h, h, s.level - 1, m, b, r, s.c22, w };
	}
	whitted_aa_write(&sc, film, aov, (first_row + y) * p->width + x, sum);
	film_add_counts(counters, counts);
}
#endif

/* Without anti-aliasing (-A): one trace at each pixel's centre, as povray -A. */
#if !defined(KERNELS_SOME) || defined(KERNELS_WHITTED)   /* lower_kernel_options: the kernels a render launches */
kernel void render_whitted(SCENE_BUFFERS(SCENE_PARAM) global const dev_params *p, global long4 *film,
                           global uint *counters, global float4 *aov)
{
	int pixel = get_global_id(0);
	if (pixel >= p->width * p->height)
		return;
	uint counts[COUNT_N] = { 0 };
	scene_data sc = { SCENE_BUFFERS(SCENE_FIELD) p, counts };
	long4 acc = film[pixel];
	media_stack around = media_around(&sc, p->cam_location.xyz);
	for (int s = 0; s < p->samples_per_pass; s++) {   /* one sample: the image is deterministic */
		first_hit first = { (float3)(0.0f), (float3)(0.0f), 0.0f, -1 };
		uint tests = counts[COUNT_NODES + RAY_CAMERA] + counts[COUNT_PRIMS + RAY_CAMERA];
		float4 c = whitted_trace(&sc, (real)(pixel % p->width), (real)(pixel / p->width), around, &first);
		acc += film_fixed(c.xyz, counts[COUNT_NODES + RAY_CAMERA] + counts[COUNT_PRIMS + RAY_CAMERA] - tests);
		if (p->aov) {
			film_add_aov(aov, pixel, &first, p->sample_base + s);
			film_add_transm(aov, pixel, c.w);
		}
	}
	film[pixel] = acc;
	film_add_counts(counters, counts);
}
#endif
