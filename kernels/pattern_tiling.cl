/* pattern_tiling.cl: POV-Ray 3.7's tiling pattern (J. Grimbert's tilings of
 * the x-z plane, pattern.cpp). Each tiling folds the point into one cell of
 * its period by its symmetries, then measures how far it is from the edge of
 * the tile it is in: the value is 0 at the middle of a tile and 1 on its
 * border. A tiling of several kinds of tile gives each kind a third (or a
 * half) of [0, 1]: kind k fills [k/n, (k+1)/n], so one colour_map colours
 * every kind apart. The folds, the tiles' order and the few values POV-Ray
 * nudges off a boundary (0.500000000001, 2.0000001) are POV-Ray's, so that a
 * colour_map gives its pixels. */

#define TILING_SQRT3 1.7320508075688772f
#define TILING_SQRT3_2 0.8660254037844386f
#define TILING_SQRT2 1.4142135623730951f
#define TILING_SQRT2_2 0.7071067811865476f
/* POV-Ray keeps a tile kind's border inside the kind (0.500000000001,
 * (5.0000001 - 3) / 3): the next floats up. */
#define TILING_ABOVE_HALF 0.50000006f
#define TILING_ABOVE_TWO_THIRDS 0.66666675f

/* v modulo a period, in [0, period). */
static float tiling_wrap(float v, float period)
{
	return v - period * floor(v / period);
}

/* 1: squares of side 1. */
static float tiling_square(float x, float z)
{
	x = fabs(x);
	z = fabs(z);
	x = 2.0f * fabs(x - floor(x) - 0.5f);
	z = 2.0f * fabs(z - floor(z) - 0.5f);
	return fmax(x, z);
}

/* 2: hexagons of side 1, their centres on x = 1.5 k. The cell is 3 by sqrt 3;
 * it folds onto the triangle between a hexagon's centre and two corners. */
static float tiling_hexagon(float x, float z)
{
	x = tiling_wrap(x + 0.5f, 3.0f);
	z = tiling_wrap(z, TILING_SQRT3);
	if (z > TILING_SQRT3_2)
		z = TILING_SQRT3 - z;
	if (x > 1.5f) {
		x -= 1.5f;
		z = TILING_SQRT3_2 - z;
	}
	if (TILING_SQRT3 * x + z < TILING_SQRT3_2) {
		x = 0.5f - x;
		z = TILING_SQRT3_2 - z;
	}
	if (x > 1.0f)
		x = 2.0f - x;
	float across = 1.0f - z / TILING_SQRT3_2;
	float slant = 1.0f - (TILING_SQRT3 * x + z - TILING_SQRT3_2) / TILING_SQRT3;
	return clamp(fmax(across, slant), 0.0f, 1.0f);
}

/* 3: equilateral triangles of side 1; those pointing up and those pointing
 * down take [0, 0.5] and [0.5, 1]. */
static float tiling_triangle(float x, float z)
{
	int kind = 0;
	x -= floor(x);
	z = tiling_wrap(z, TILING_SQRT3);
	if (z > TILING_SQRT3_2) {
		z = TILING_SQRT3 - z;
		kind = 1;
	}
	if (x > 0.5f)
		x = 1.0f - x;
	if (x == 0.0f) {   /* POV-Ray's vertical edge: folded, its kind kept */
		z = TILING_SQRT3_2 - z;
		x = 0.5f;
	} else if (z / x > TILING_SQRT3) {
		z = TILING_SQRT3_2 - z;
		x = 0.5f - x;
		kind = 1 - kind;
	}
	float base = 1.0f - z * 2.0f * TILING_SQRT3;
	float side = 1.0f - (TILING_SQRT3 * x - z) * TILING_SQRT3;
	return 0.5f * kind + 0.5f * fmax(base, side);
}

/* The lozenge (a rhombus of two equilateral triangles) a point of [-0.25,
 * 0.75] x [0, sqrt3/4] is in, folded: its distance from the lozenge's centre
 * line, 0 in the middle, 1 on the border. Lozenges and rhombus share it. */
static float tiling_lozenge_cell(float x, float z)
{
	if (2.0f * z > TILING_SQRT3_2) {
		z = TILING_SQRT3_2 - z;
		x = 1.5f - x;
	}
	if (x > 0.75f)
		x -= 1.0f;
	if (x != 0.0f && z / x > TILING_SQRT3) {
		z = TILING_SQRT3_2 - z;
		x = 0.5f - x;
	}
	float across = 1.0f - z * 4.0f * TILING_SQRT3 / 3.0f;
	float slant = 1.0f - fabs(TILING_SQRT3 * x - z) * TILING_SQRT3 * 2.0f / 3.0f;
	return fmax(across, slant);
}

/* 4: lozenges, all turned the same way. */
static float tiling_lozenge(float x, float z)
{
	x -= floor(x);
	z = tiling_wrap(z, TILING_SQRT3);
	if (z > TILING_SQRT3_2) {
		z -= TILING_SQRT3_2;
		x += 0.5f;
	}
	return tiling_lozenge_cell(x, z);
}

/* 5: lozenges in three directions (the cube seen along its diagonal), one
 * third of [0, 1] each. */
static float tiling_rhombus(float x, float z)
{
	int kind = 0;
	x = tiling_wrap(x + 0.5f, 3.0f);
	z = tiling_wrap(z, TILING_SQRT3);
	if (z > TILING_SQRT3_2) {
		z = TILING_SQRT3 - z;
		kind = 2 - kind;
	}
	if (x > 1.5f) {
		x -= 1.5f;
		z = TILING_SQRT3_2 - z;
		kind = 2 - kind;
	}
	if (x < 0.5f) {
		x = 1.0f - x;
		kind = 2 - kind;
	}
	x -= 0.5f;
	if (x == 0.0f || z / x > TILING_SQRT3) {   /* the upright lozenge: turned by 60 degrees */
		float turned_x = 0.5f * x + TILING_SQRT3_2 * z;
		float turned_z = 0.5f * z - TILING_SQRT3_2 * x;
		x = turned_x;
		z = turned_z;
		kind = 1;
	}
	float v = tiling_lozenge_cell(x, z) / 3.0f + kind / 3.0f;
	return clamp(v, 0.0f, 1.0f);
}

/* Distance to the border of a 2 by 1 rectangle, 0 on its centre line: along
 * x (long is x) or along z, point relative to the rectangle's long side's
 * middle. */
static float tiling_long_x(float x, float z)
{
	return fmax(2.0f * (fmax(fabs(x), 0.5f) - 0.5f), 2.0f * fabs(z - 0.5f));
}

static float tiling_long_z(float x, float z)
{
	return fmax(2.0f * fabs(x - 0.5f), 2.0f * (fmax(fabs(z), 0.5f) - 0.5f));
}

/* 7: octagons and squares. */
static float tiling_octa_square(float x, float z)
{
	const float period = TILING_SQRT2 + 1.0f;
	x = fabs(tiling_wrap(x, period) - (TILING_SQRT2_2 + 0.5f));
	z = fabs(tiling_wrap(z, period) - (TILING_SQRT2_2 + 0.5f));
	if (z > x) {
		float t = x;
		x = z;
		z = t;
	}
	if (x + z < TILING_SQRT2_2)   /* the square, turned by 45 degrees */
		return (x + z) / TILING_SQRT2;
	float across = 1.0f - z;
	float slant = (TILING_SQRT2 + TILING_SQRT2_2 - (x + z)) / TILING_SQRT2;
	return fmax(TILING_ABOVE_HALF, fmax(across, slant));
}

/* 8: rows of squares between rows of triangles: the triangles (up, down) in
 * the first two thirds, the squares in the last. */
static float tiling_square_triangle(float x, float z)
{
	int kind = 0;
	x -= floor(x);
	z = tiling_wrap(z, 2.0f + TILING_SQRT3);
	if (z > TILING_SQRT3_2 + 1.0f) {
		z -= TILING_SQRT3_2 + 1.0f;
		x += x > 0.5f ? -0.5f : 0.5f;
	}
	if (x > 0.5f)
		x = 1.0f - x;
	z -= 1.0f;
	if (z > 0.0f) {   /* a triangle */
		if (x == 0.0f) {
			z = TILING_SQRT3_2 - z;
			x = 0.5f;
			kind = 1;
		} else if (z / x > TILING_SQRT3) {
			z = TILING_SQRT3_2 - z;
			x = 0.5f - x;
			kind = 1;
		}
		float base = 1.0f - 2.0f * z * TILING_SQRT3;
		float side = 1.0f - (TILING_SQRT3 * x - z) * TILING_SQRT3;
		return (kind + fmax(base, side)) / 3.0f;
	}
	if (z < -0.5f)   /* a square */
		z = -1.0f - z;
	float dx = 2.0f + 2.0f * TILING_SQRT3 * fabs(x);
	float dz = 2.0f + 2.0f * TILING_SQRT3 * fabs(z);
	return fmax((5.0f - fmin(dx, dz)) / 3.0f, TILING_ABOVE_TWO_THIRDS);
}

/* 9: hexagons, each surrounded by triangles (the trihexagonal tiling). */
static float tiling_hexa_triangle(float x, float z)
{
	int kind = 0;
	x = tiling_wrap(x + 0.5f, 2.0f);
	z = tiling_wrap(z, 2.0f * TILING_SQRT3);
	if (z > TILING_SQRT3) {
		z -= TILING_SQRT3;
		x += x < 1.0f ? 1.0f : -1.0f;
	}
	if (z > TILING_SQRT3_2) {
		z = TILING_SQRT3 - z;
		kind = 1;
	}
	if (x > 1.0f)
		x = 2.0f - x;
	if (TILING_SQRT3 * x + z < TILING_SQRT3_2) {   /* a triangle */
		float base = 1.0f - z * 2.0f * TILING_SQRT3;
		float side = 1.0f + (TILING_SQRT3 * x + z - TILING_SQRT3_2) * TILING_SQRT3;
		return (kind + fmax(base, side)) / 3.0f;
	}
	float across = 2.0f + 2.0f * z * TILING_SQRT3;
	float slant = 2.0f + 2.0f * (TILING_SQRT3 * x + z - TILING_SQRT3_2) * TILING_SQRT3_2;
	return fmax((5.0f - fmin(across, slant)) / 3.0f, TILING_ABOVE_TWO_THIRDS);
}

/* 10: squares in rows offset by half a square. */
static float tiling_square_offset(float x, float z)
{
	z = tiling_wrap(z, 2.0f);
	if (z > 1.0f) {
		x += 0.5f;
		z -= 1.0f;
	}
	x -= floor(x);
	return fmax(2.0f * fabs(x - 0.5f), 2.0f * fabs(z - 0.5f));
}

/* A point of the 3 by 3 cell of a square ringed by four 2 by 1 rectangles
 * (tilings 11 and 12): the square takes [0, 1/3], the rectangles along x
 * [1/3, 2/3], those along z [2/3, 1]. */
static float tiling_pinwheel_cell(float x, float z)
{
	int cell = min((int)x, 2) + 3 * min((int)z, 2);
	switch (cell) {
	case 0: case 3:
		return (tiling_long_z(x, z - 1.0f) + 2.0f) / 3.0f;
	case 1: case 2:
		return (tiling_long_x(x - 2.0f, z) + 1.0f) / 3.0f;
	case 4:
		return fmax(2.0f * fabs(x - 1.5f), 2.0f * fabs(z - 1.5f)) / 3.0f;
	case 5: case 8:
		return (tiling_long_z(x - 2.0f, z - 2.0f) + 2.0f) / 3.0f;
	default:   /* 6, 7 */
		return (tiling_long_x(x - 1.0f, z - 2.0f) + 1.0f) / 3.0f;
	}
}

/* 11: the pinwheel of a square and four rectangles, repeated. */
static float tiling_square_rectangle(float x, float z)
{
	return tiling_pinwheel_cell(tiling_wrap(x, 3.0f), tiling_wrap(z, 3.0f));
}

/* 12: the same pinwheel, mirrored across each cell's sides. */
static float tiling_rectangle_square(float x, float z)
{
	return tiling_pinwheel_cell(fabs(tiling_wrap(x, 6.0f) - 3.0f), fabs(tiling_wrap(z, 6.0f) - 3.0f));
}

/* Tilings 6 and 18: 2 by 1 rectangles in a 4 by 4 cell, whose sixteen unit
 * squares (x + 4 z) each name the shift to their rectangle's reference
 * corner and, by a bit of along_z, its direction: those along z take [0.5, 1],
 * those along x [0, 0.5]. */
constant float tiling_rectangle_dx[16] = { 0, 2, 2, 3, 0, 1, 3, 3, 0, 1, 2, 4, 1, 1, 2, 3 };
constant float tiling_rectangle_dz[16] = { 1, 0, 0, 0, 1, 2, 1, 1, 2, 2, 3, 2, 3, 3, 3, 4 };
constant float tiling_pair_dx[16] = { 0, 1, 3, 3, 0, 1, 3, 3, 1, 1, 2, 3, 1, 1, 2, 3 };
constant float tiling_pair_dz[16] = { 1, 1, 0, 0, 1, 1, 1, 1, 2, 2, 3, 3, 3, 3, 3, 3 };

static float tiling_dominoes(float x, float z, constant float *dx, constant float *dz, int along_z)
{
	x = tiling_wrap(x, 4.0f);
	z = tiling_wrap(z, 4.0f);
	int cell = min((int)x, 3) + 4 * min((int)z, 3);
	x -= dx[cell];
	z -= dz[cell];
	if (along_z >> cell & 1)
		return fabs(0.5f * tiling_long_z(x, z) + 0.5f);
	return fabs(0.5f * tiling_long_x(x, z));
}

/* Tilings 13 and 14: squares turned by 45 degrees, each ringed by four
 * rectangles (the cell is 4 / sqrt 2, folded into a quarter [0, 2]^2). The
 * value's parts: the square's, and a rectangle's along x or z with the
 * distance to its diagonal end. Thirteen gives the square [0, 1/3] and the
 * rectangles [1/3, 2/3] (along z) and [2/3, 1] (along x); fourteen gives five
 * kinds, the rectangles by side of the square they lie on. */
static float tiling_square_internal(float x, float z, int five)
{
	x = tiling_wrap(x * TILING_SQRT2, 4.0f) - 2.0f;
	z = tiling_wrap(z * TILING_SQRT2, 4.0f) - 2.0f;
	int side_x = x < 0.0f ? 1 : 0, side_z = z < 0.0f ? 2 : 3;
	x = fabs(x);
	z = fabs(z);
	/* not clamped: at x = 0 the fold gives 2, and POV-Ray's switch reads
	 * cell 2 (or no case, 0) there */
	int cell = (int)x + 2 * (int)z;
	if (cell > 3)
		return 0.0f;
	if (cell == 0) {
		float m = fmax(2.0f * fmax(x - 0.5f, 0.0f), 2.0f * fmax(z - 0.5f, 0.0f));
		return five ? (4.000001f + m) / 5.0f : m / 3.0f;
	}
	float end = 1.0f - TILING_SQRT2 * fabs(x - z);
	if (cell == 1 || (cell == 3 && x > z)) {
		float v = 2.0f * fabs(1.5f - x);
		if (z > 0.5f)
			v = fmax(v, end);
		return five ? (v + side_x) / 5.0f : (v + 2.0f) / 3.0f;
	}
	float v = 2.0f * fabs(1.5f - z);
	if (x > 0.5f)
		v = fmax(v, end);
	return five ? (v + side_z) / 5.0f : (v + 1.0f) / 3.0f;
}

/* 15: squares of side 1 and 2 in a 5 by 5 cell; the small ones take
 * [0, 0.5], the big ones (0.5, 1]. Per unit square (x + 5 z), the shift to
 * its square's reference point. */
constant float tiling_double_dx[25] = { 0, 2, 2, 4, 4, 1, 1, 2, 4, 4, 1, 1, 3, 3, 4, 0, 1, 3, 3, 5, 0, 2, 2, 3, 5 };
constant float tiling_double_dz[25] = { 0, 0, 0, 1, 1, 2, 2, 1, 1, 1, 2, 2, 3, 3, 2, 4, 3, 3, 3, 4, 4, 5, 5, 4, 4 };

static float tiling_square_double(float x, float z)
{
	const int small = 1 << 0 | 1 << 7 | 1 << 14 | 1 << 16 | 1 << 23;
	x = tiling_wrap(x, 5.0f);
	z = tiling_wrap(z, 5.0f);
	int cell = min((int)x, 4) + 5 * min((int)z, 4);
	x -= tiling_double_dx[cell];
	z -= tiling_double_dz[cell];
	if (small >> cell & 1)
		return 0.5f * fmax(2.0f * fabs(x - 0.5f), 2.0f * fabs(z - 0.5f));
	float m = fmax(2.0f * (fmax(fabs(x), 0.5f) - 0.5f), 2.0f * (fmax(fabs(z), 0.5f) - 0.5f));
	return fmax(0.5f * m + 0.5f, TILING_ABOVE_HALF);
}

/* Tilings 16 and 17: hexagons, squares and triangles (the rhombitrihexagonal
 * tiling). The cell folds onto [0, 1 + sqrt3/2]^2, and the lower left part
 * turns by 60 degrees onto the rest, counting the folds and the turn. Sixteen
 * gives squares [0, 1/3], triangles [1/3, 2/3], hexagons (2/3, 1]; seventeen
 * gives the three squares' directions, the two triangles' and the hexagon a
 * sixth each. */
static float tiling_hexa_square_triangle(float x, float z, int six)
{
	const float h = TILING_SQRT3_2;
	int mir_x = 0, mir_z = 0, turned = 0;
	x = tiling_wrap(x + 0.5f, 3.0f + TILING_SQRT3);
	z = tiling_wrap(z, 2.0f * (1.0f + TILING_SQRT3));
	if (x > h + 1.5f) {
		x -= h + 1.5f;
		z += z < TILING_SQRT3 + 1.0f ? h + 0.5f : -(h + 0.5f);
	}
	if (z > TILING_SQRT3 + 1.0f)
		z -= TILING_SQRT3 + 1.0f;
	if (z > 0.5f + h) {
		z = TILING_SQRT3 + 1.0f - z;
		mir_z = 1;
	}
	if (x > 1.0f + h) {
		x = TILING_SQRT3 + 2.0f - x;
		mir_x = 1;
	}
	if (TILING_SQRT3 * x + z < h + 2.0f && x < 0.5f + h) {
		float u = x - (1.0f + h), w = z - (0.5f + h);
		x = 0.5f * u - h * w + 1.0f + h;
		z = 0.5f * w + h * u + 0.5f + h;
		turned = 1;
		if (z < 0.0f)
			z = -z;
		if (x > 1.0f + h) {
			x = TILING_SQRT3 + 2.0f - x;
			mir_x ^= 1;
			mir_z ^= 1;
		}
	}
	if (!(TILING_SQRT3 * x + z < h + 2.0f) && !(z < 0.5f)) {   /* the hexagon */
		float w = fabs(z - 0.5f), u = fabs(x - h);
		float m = fmin(2.0f * w * TILING_SQRT3, (TILING_SQRT3 * u + w) * TILING_SQRT3 - 1.5f);
		if (six)
			return fmax(6.0f - m, 5.000001f) / 6.0f;
		return fmax((3.0f - m) / 3.0f, TILING_ABOVE_TWO_THIRDS);
	}
	if (!(z < 0.5f))
		return 0.0f;
	if (x > h + 0.5f) {   /* a square */
		float u = x - (h + 0.5f), w = z - 0.5f;
		float m = fmax(fmax(1.0f + 2.0f * TILING_SQRT3 * w, 0.0f), fmax(1.0f - 2.0f * TILING_SQRT3 * u, 0.0f));
		if (six)
			return (m + turned * (1.000001f + (mir_x + mir_z) % 2)) / 6.0f;
		return m / 3.0f;
	}
	float u = fabs(x - (h + 0.5f));   /* a triangle */
	float m = fmax(2.0f - 2.0f * TILING_SQRT3 * u, (TILING_SQRT3 * z + u) * TILING_SQRT3 + 0.5f);
	if (six)
		return (m + ((turned + mir_x) % 2 ? 2.0f : 3.0f)) / 6.0f;
	return m / 3.0f;
}

/* The triangles of tilings 19 and 20 (as tiling 3's, but POV-Ray's vertical
 * edge switches the kind here), after kind: a third each, up and down. */
static float tiling_small_triangle(float x, float z, int kind)
{
	x -= floor(x);
	z = tiling_wrap(z, TILING_SQRT3);
	if (z > TILING_SQRT3_2) {
		z = TILING_SQRT3 - z;
		kind = 1 - kind;
	}
	if (x > 0.5f)
		x = 1.0f - x;
	if (x == 0.0f || z / x > TILING_SQRT3) {
		z = TILING_SQRT3_2 - z;
		x = x == 0.0f ? 0.5f : 0.5f - x;
		kind = 1 - kind;
	}
	float base = 1.0f - z * 2.0f * TILING_SQRT3;
	float side = 1.0f - (TILING_SQRT3 * x - z) * TILING_SQRT3;
	return (kind + fmax(base, side)) / 3.0f;
}

/* Tilings 19 and 20: hexagons in a sea of triangles (the snub hexagonal
 * tiling), turning right or left. Each band of three rows of triangles is
 * shifted by half a triangle (POV-Ray's integer arithmetic, kept), then the
 * 7 by 3 sqrt3/2 cell is cut and moved onto one hexagon. The triangles take
 * [0, 2/3], the hexagons (2/3, 1]. */
static float tiling_hexa_tri(float x, float z, int left)
{
	int band = (int)(z / TILING_SQRT3_2) / 3;
	if (z < 0.0f)
		band -= 1;
	x += left ? -band / 2.0f : band / 2.0f;
	z = tiling_wrap(z, 3.0f * TILING_SQRT3_2);
	x = tiling_wrap(x + 7.0f, 7.0f);
	if (left) {
		if (x > 2.0f && z < TILING_SQRT3_2) {
			x -= 2.0f;
			z += TILING_SQRT3;
		}
		if (x > 4.5f && z < TILING_SQRT3) {
			x -= 4.5f;
			z += TILING_SQRT3_2;
		}
		if (x > 2.5f && z > TILING_SQRT3) {
			x -= 2.5f;
			z -= TILING_SQRT3_2;
		}
	} else {
		if (x > 4.5f && z > TILING_SQRT3) {
			x -= 4.5f;
			z -= TILING_SQRT3_2;
		}
		if (x > 5.0f && z < TILING_SQRT3_2) {
			x -= 5.0f;
			z += TILING_SQRT3;
		}
		if (x > 2.5f && z < TILING_SQRT3) {
			x -= 2.5f;
			z += TILING_SQRT3_2;
		}
	}
	int kind = 0;
	int row = (int)(z / TILING_SQRT3_2);
	if (row == 2) {
		row = 1;
		z = 2.0f * TILING_SQRT3 - z;
		kind = 1;
	}
	if (!row || x > 2.0f || z + TILING_SQRT3 * x < TILING_SQRT3 || TILING_SQRT3 * x - z > TILING_SQRT3)
		return tiling_small_triangle(x, z, kind);
	z -= TILING_SQRT3_2;
	if (x > 1.0f)
		x = 2.0f - x;
	float across = 2.0f + 2.0f * z * TILING_SQRT3;
	float slant = 2.0f + 2.0f * (TILING_SQRT3 * x + z - TILING_SQRT3_2) * TILING_SQRT3_2;
	return fmax(5.0f - fmin(across, slant), 2.000001f) / 3.0f;
}

/* 21: squares and triangles (the snub square tiling); the four triangles'
 * directions take a sixth each of [0, 2/3], the squares' two directions
 * [2/3, 5/6] and (5/6, 1]. */
static float tiling_square_tri(float x, float z)
{
	const float mid = TILING_SQRT3_2 + 0.5f;
	int flipped = 0, mirrored_x = 0, kind = 0;
	x = tiling_wrap(x, 1.0f + TILING_SQRT3);
	z = tiling_wrap(z, 1.0f + TILING_SQRT3);
	if (z > mid) {
		z = 1.0f + TILING_SQRT3 - z;
		flipped = 1;
	}
	if (x > mid) {
		x = 1.0f + TILING_SQRT3 - x;
		flipped = 1 - flipped;
		mirrored_x = 1;
	}
	int flop_x = 2.0f * x + (TILING_SQRT3 - 1.0f) * 2.0f * z / (TILING_SQRT3 + 1.0f) > TILING_SQRT3;
	int flop_z = 2.0f * z * TILING_SQRT3 + (TILING_SQRT3 - 3.0f) * 2.0f * x / (TILING_SQRT3 + 1.0f) > TILING_SQRT3;
	float t;
	switch (flop_x + 2 * flop_z) {
	case 0:
		kind = 2 * mirrored_x;
		break;
	case 1:   /* turned clockwise */
		kind = mirrored_x ? 1 + 2 * flipped : 3 - 2 * flipped;
		t = x;
		x = z;
		z = mid - t;
		break;
	case 2:   /* turned the other way */
		kind = mirrored_x ? 3 - 2 * flipped : 1 + 2 * flipped;
		t = z;
		z = x;
		x = mid - t;
		break;
	default:   /* point symmetry */
		kind = mirrored_x ? 0 : 2;
		x = mid - x;
		z = mid - z;
		break;
	}
	if (x == 0.0f)
		z = 0.0f;
	float s = z * 2.0f * TILING_SQRT3 - TILING_SQRT3 + x * 2.0f;
	if (s < 0.0f) {   /* a triangle */
		float m = fmin(-1.5f / TILING_SQRT3 * s, 2.0f * x * TILING_SQRT3);
		return (kind + 1.0f - m) / 6.0f;
	}
	s = fmin(s * 1.5f / TILING_SQRT3, 1.0f);   /* a square */
	if (flipped)
		return fmin(fmax((6.0f - s) / 6.0f, 5.000001f / 6.0f), 1.0f);
	return fmax(fmin((5.0f - s) / 6.0f, 5.0f / 6.0f), 4.000001f / 6.0f);
}

/* 22: dodecagons and triangles (the truncated hexagonal tiling): the
 * triangles' two directions [1/3, 2/3] and [2/3, 1]... as POV-Ray counts
 * them: (1 + toggle + distance) / 3, the dodecagons (2/3, 1]. */
static float tiling_dodeca_tri(float x, float z)
{
	int toggle = 0;
	x = tiling_wrap(x, 2.0f + TILING_SQRT3);
	z = tiling_wrap(z, 3.0f + 2.0f * TILING_SQRT3);
	if (z > TILING_SQRT3 + 1.5f) {
		z -= TILING_SQRT3 + 1.5f;
		x += (x < 1.0f + TILING_SQRT3_2 ? 1.0f : -1.0f) * (1.0f + TILING_SQRT3_2);
	}
	if (x > 1.0f + TILING_SQRT3_2)
		x = 2.0f + TILING_SQRT3 - x;
	if (z > 1.0f + TILING_SQRT3_2) {
		z = 2.0f + TILING_SQRT3 - z;
		toggle = 1;
	}
	float d2 = x - TILING_SQRT3_2 - 0.5f + z * TILING_SQRT3;
	if (d2 < 0.0f) {   /* turned by 120 degrees about the triangle's centre */
		float u = x, w = z;
		x = (1.0f + TILING_SQRT3) / 4.0f + 0.5f * u - TILING_SQRT3_2 * w;
		z = (3.0f + TILING_SQRT3) / 4.0f - TILING_SQRT3_2 * u - 0.5f * w;
		d2 = -d2;
	}
	float d1 = z * 3.0f;
	float d3 = (z - TILING_SQRT3_2 - 0.5f + x * TILING_SQRT3) * TILING_SQRT3;
	float d4 = x * 3.0f;
	d2 *= TILING_SQRT3;
	if (d3 < 0.0f)
		return (fmax(d3, -1.0f) + 1.0f + toggle) / 3.0f;
	float m = fmin(fmin(fmin(d1, d2), fmin(d3, d4)), 1.0f);
	return fmax((3.0f - m) / 3.0f, TILING_ABOVE_TWO_THIRDS);
}

/* Tilings 23 and 24: dodecagons, hexagons and squares (the truncated
 * trihexagonal tiling). Twenty-three gives hexagons [0, 1/3], squares
 * [1/3, 2/3], dodecagons (2/3, 1]; twenty-four splits the squares by
 * direction into fifths: hexagons [0, 1/5], squares [1/5, 2/5] and (by the
 * folds) [2/5, 3/5] or [3/5, 4/5], dodecagons (4/5, 1]. */
static float tiling_dodeca_hex(float x, float z, int five)
{
	int mirrors = 0;
	x = tiling_wrap(x, 3.0f + TILING_SQRT3);
	z = tiling_wrap(z, 3.0f + 3.0f * TILING_SQRT3);
	if (z > 1.5f * TILING_SQRT3 + 1.5f) {
		z -= 1.5f * TILING_SQRT3 + 1.5f;
		x += (x < 1.5f + TILING_SQRT3_2 ? 1.0f : -1.0f) * (1.5f + TILING_SQRT3_2);
	}
	if (x > 1.5f + TILING_SQRT3_2) {
		x = 3.0f + TILING_SQRT3 - x;
		mirrors++;
	}
	if (z > 1.0f + TILING_SQRT3) {
		z = 2.0f + 2.0f * TILING_SQRT3 - z;
		mirrors++;
	}
	if (x - TILING_SQRT3_2 - 1.5f + z * TILING_SQRT3 < 0.0f) {
		float u = x, w = z;
		x = (3.0f + TILING_SQRT3) / 4.0f + 0.5f * u - TILING_SQRT3_2 * w;
		z = (3.0f + 3.0f * TILING_SQRT3) / 4.0f - TILING_SQRT3_2 * u - 0.5f * w;
	}
	float d2 = x - TILING_SQRT3_2 - 2.5f + z * TILING_SQRT3;
	float d1 = z * 2.0f - TILING_SQRT3;
	float d3 = z - 1.5f * TILING_SQRT3 - 0.5f + x * TILING_SQRT3;
	float d4 = (x - 0.5f) * 2.0f;
	float scale = five ? 5.0f : 3.0f;
	if (d2 >= 0.0f && d1 >= 0.0f && d3 >= 0.0f && d4 >= 0.0f) {   /* the dodecagon */
		float m = fmin(fmin(fmin(d1, d2), fmin(d3, d4)), 1.0f);
		return ((five ? 5.000001f : 3.000001f) - m) / scale;
	}
	float d5 = 2.0f * z - 2.0f * TILING_SQRT3 - 1.0f;
	if (d5 >= 0.0f)   /* the square across the top */
		return (2.0f - fmin(d5, -d4)) / scale;
	float d6 = TILING_SQRT3 * x - z - TILING_SQRT3_2 + 0.5f;
	float d7 = d6 - 2.0f;
	if (d6 < 0.0f && d7 < 0.0f)   /* the hexagon on the left */
		return (1.0f - fmin(fmin(-d6, -d3), fmin(-d5, 1.0f))) / scale;
	if (d6 >= 0.0f && d7 >= 0.0f)   /* the hexagon below */
		return (1.0f - fmin(fmin(d7, -d1), 1.0f)) / scale;
	float m = fmin(fmin(d6, -d2), -d7);   /* the slanted square */
	return ((five ? mirrors % 2 + 3.0f : 2.0f) - m) / scale;
}

/* ---- Penrose tilings (25 to 27) ----
 * POV-Ray draws them by deflation: a point is taken to the level where it
 * lies in one of the five sectors of the central figure, then, level by
 * level, into the smaller tile of the subdivision it falls in (scaled up by
 * the golden ratio each time), down to a single tile, whose borders give the
 * value. POV-Ray recurses; each step here is one turn of a loop. */
#define TILING_PHI 1.6180339887498949f
#define TILING_INVPHI 0.6180339887498949f
#define TILING_SQRPHI 2.6180339887498949f
#define TILING_INVSQRPHI 0.3819660112501052f
#define TILING_SIN18 0.3090169943749474f
#define TILING_SIN36 0.5877852522924731f
#define TILING_SIN54 0.8090169943749474f
#define TILING_SIN72 0.9510565162951536f
#define TILING_TAN18 0.3249196962329063f
#define TILING_TAN36 0.7265425280053609f
#define TILING_TAN54 1.3763819204711736f
#define TILING_TAN72 3.0776835371752535f
#define TILING_EPS 1e-6f
/* the angles past 90 degrees, from the ones above */
#define TILING_COS36 TILING_SIN54
#define TILING_COS72 TILING_SIN18
#define TILING_COS18 TILING_SIN72
#define TILING_COS108 (-TILING_SIN18)
#define TILING_COS144 (-TILING_SIN54)
#define TILING_SIN108 TILING_SIN72
#define TILING_SIN144 TILING_SIN36

/* (x, z) turned by the angle of (c, s), as POV-Ray's rotX, rotZ: x c + z s,
 * z c - x s. */
static float2 tiling_turn(float x, float z, float c, float s)
{
	return (float2)(x * c + z * s, z * c - x * s);
}

/* The five-fold symmetry: folds (x, |z|), at distance r from the centre, into
 * the sector within 36 degrees of +x. */
static float2 tiling_penrose_fold(float x, float z, float r)
{
	z = fabs(z);
	if (x < r * TILING_COS36) {
		float2 t = x < r * TILING_COS108 ? tiling_turn(x, z, TILING_COS144, TILING_SIN144)
		                                 : tiling_turn(x, z, TILING_COS72, TILING_SIN72);
		return (float2)(t.x, fabs(t.y));
	}
	return (float2)(x, z);
}

/* 26, 27: kites and darts (P2), or thick and thin rhombs (P3), as half
 * tiles; thin rhombs and kites take [0, 0.5), thick rhombs and darts (0.5, 1].
 * POV-Ray's 4.46 and 5.55 scale the borders' widths. */
static float tiling_penrose(float x, float z, int rhombs)
{
	float r = sqrt(x * x + z * z);
	if (r <= 1e-10f)
		return 1.0f;
	float2 q = tiling_penrose_fold(x, z, r);
	x = q.x;
	z = q.y;
	if (rhombs) {
		x *= TILING_INVPHI;
		z *= TILING_INVPHI;
	}
	float dist = fabs(TILING_SIN108 * x - TILING_COS108 * z) / TILING_COS18;
	int depth = max(0, (int)ceil(log(dist) / log(TILING_SQRPHI)));
	float shrink = pow(TILING_INVSQRPHI, (float)depth);
	x *= shrink;
	z *= shrink;
	if (depth % 2) {
		q = tiling_turn(x, z, TILING_COS36, TILING_SIN36);
		x = q.x;
		z = fabs(q.y);
	}
	depth *= 2;
	int kite = 1;
	for (; depth > 0; depth--) {
		z = fabs(z);
		if (kite && z < (x - TILING_INVPHI) * -TILING_TAN36) {
			kite = 0;
		} else if (kite) {
			q = tiling_turn(x - TILING_COS36, z - TILING_SIN36, TILING_COS108, -TILING_SIN108);
			x = q.x;
			z = q.y;
		} else if (z < (x - TILING_INVPHI) * -TILING_TAN72) {
			q = tiling_turn(x, z, TILING_COS36, TILING_SIN36);
			x = q.x;
			z = q.y;
			kite = 1;
		} else {
			q = tiling_turn(x - 1.0f, z, TILING_COS144, TILING_SIN144);
			x = q.x;
			z = q.y;
		}
		x *= TILING_PHI;
		z *= TILING_PHI;
	}
	z = fabs(z);
	float width = rhombs ? 5.55f : 4.46f;
	if (kite && rhombs && z < (x - TILING_INVPHI) * TILING_TAN72) {
		float d1 = fabs(TILING_SIN72 * (x - TILING_INVPHI) - TILING_COS72 * z) * width;
		float d2 = fabs(TILING_SIN108 * (x - 1.0f) - TILING_COS108 * z) * width;
		return fmax(fmax(1.0f - d1 / 2.0f, 1.0f - d2 / 2.0f), 0.5f + TILING_EPS);
	}
	if (kite && rhombs) {
		float d1 = fabs(z) * width;
		float d2 = fabs(TILING_SIN72 * (x - TILING_INVPHI) - TILING_COS72 * z) * width;
		return fmin(fmax(fmax(0.5f - d1 / 2.0f, 0.5f - d2 / 2.0f), 0.0f), 0.5f - TILING_EPS);
	}
	if (kite || rhombs) {   /* a kite, or a dart's half of a thin rhomb */
		float d1 = fabs(TILING_SIN36 * x - TILING_COS36 * z) * width;
		float d2 = kite ? fabs(TILING_SIN108 * (x - 1.0f) - TILING_COS108 * z) * width
		                : fabs(TILING_SIN144 * (x - 1.0f) - TILING_COS144 * z) * width;
		return fmin(fmax(fmax(0.5f - d1 / 2.0f, 0.5f - d2 / 2.0f), 0.0f), 0.5f - TILING_EPS);
	}
	float d1 = fabs(z) * width;   /* a dart */
	float d2 = fabs(TILING_SIN144 * (x - 1.0f) - TILING_COS144 * z) * width;
	return fmax(fmax(1.0f - d1 / 2.0f, 1.0f - d2 / 2.0f), 0.5f + TILING_EPS);
}

/* 25: pentagons, stars, boats and diamonds (P1). The shapes, in the order of
 * their sixths of [0, 1]: the three kinds of pentagon, the star, the boat, the
 * diamond. A pentagon of the second kind may lie inside a quadrilateral of the
 * subdivision and one of the third kind or a boat inside a wedge; a diamond has
 * two sides. */
enum { PENROSE_PENTAGON1, PENROSE_PENTAGON2, PENROSE_PENTAGON3, PENROSE_STAR, PENROSE_BOAT, PENROSE_DIAMOND };

/* How far (x, z) is from the border of a pentagon in the first sector. */
static float tiling_pentagon_dist(float x)
{
	return fabs(x - 0.5f / TILING_TAN36) * 5.55f * TILING_INVPHI;
}

static float tiling_penrose1(float x, float z)
{
	const float a = 0.5f / TILING_SIN36;   /* a pentagon's corner radius at this level */
	float r = sqrt(x * x + z * z);
	if (r <= 1e-10f)
		return 1.0f;
	float2 q = tiling_penrose_fold(x, z, r);
	x = q.x;
	z = q.y;
	int depth = max(0, (int)ceil(log(x * 2.0f * TILING_TAN36) / log(TILING_SQRPHI * TILING_SQRPHI)));
	float shrink = pow(TILING_INVSQRPHI * TILING_INVSQRPHI, (float)depth);
	x *= shrink;
	z *= shrink;
	depth *= 4;
	int shape = PENROSE_PENTAGON1, flag = 0;
	for (;; depth--) {
		z = fabs(z);
		if (shape == PENROSE_PENTAGON1) {
			q = tiling_penrose_fold(x, z, sqrt(x * x + z * z));
			x = q.x;
			z = q.y;
		}
		if (depth <= 0)
			break;
		switch (shape) {
		case PENROSE_PENTAGON1:
			if (z < (x - 0.5f / TILING_TAN36) * TILING_TAN54 + 0.5f) {
				x = x - 0.5f / TILING_TAN36 - TILING_INVPHI * 0.5f * TILING_COS72 / TILING_SIN36;
				shape = PENROSE_PENTAGON2;
				flag = 0;
			} else {
				q = tiling_turn(x, z, TILING_COS36, TILING_SIN36);
				x = q.x;
				z = q.y;
				shape = PENROSE_STAR;
			}
			break;
		case PENROSE_PENTAGON2:
			if (flag && z < (x - TILING_INVSQRPHI * a) * TILING_TAN54) {
				x -= a;
				shape = PENROSE_PENTAGON1;
			} else if (flag && z < (x - TILING_INVSQRPHI * a) * -TILING_TAN18) {
				x = -x;
				shape = PENROSE_DIAMOND;
				flag = 1;
			} else if (flag) {
				q = tiling_turn(x, z, TILING_COS108, -TILING_SIN108);
				x = q.x + TILING_INVPHI * a;
				z = q.y;
			} else if (z < (x + a) * TILING_TAN18) {
				x = x + a - TILING_INVSQRPHI * a;
				shape = PENROSE_DIAMOND;
			} else {
				q = tiling_turn(x, z, TILING_COS36, TILING_SIN36);
				x = -q.x - TILING_COS72 * a;
				z = q.y - TILING_SIN72 * a;
				shape = PENROSE_PENTAGON3;
			}
			break;
		case PENROSE_PENTAGON3:
			if (flag && x > TILING_INVSQRPHI * 0.5f * TILING_COS72 / TILING_SIN36) {
				x = -(x - TILING_INVSQRPHI * 0.5f * TILING_COS72 / TILING_SIN36 - TILING_INVPHI * 0.5f / TILING_TAN36);
				shape = PENROSE_PENTAGON2;
			} else if (!flag && x < 0.5f * TILING_COS108 / TILING_SIN36) {
				q = tiling_turn(x, z, TILING_COS144, TILING_SIN144);
				x = q.x - a;
				z = q.y;
				shape = PENROSE_PENTAGON2;
			} else if (!flag && z > (x - TILING_INVSQRPHI * a) * -TILING_TAN54) {
				q = tiling_turn(x, z, TILING_COS36, -TILING_SIN36);
				x = -q.x - TILING_COS72 * a;
				z = q.y - TILING_SIN72 * a;
			} else {
				shape = PENROSE_BOAT;
			}
			break;
		case PENROSE_STAR:
			if (x < TILING_INVPHI * 0.5f / TILING_TAN36) {
				shape = PENROSE_PENTAGON1;
			} else {
				x = -(x - TILING_INVPHI / TILING_TAN36);
				shape = PENROSE_PENTAGON3;
				flag = 1;
			}
			break;
		case PENROSE_BOAT:
			if (flag && x > TILING_PHI * 0.5f * TILING_COS108 / TILING_SIN36) {
				x = -x;
				shape = PENROSE_PENTAGON1;
			} else {
				if (!flag) {
					q = tiling_turn(x, z, TILING_COS72, -TILING_SIN72);
					x = q.x;
					z = q.y;
				}
				x += a;
				shape = PENROSE_PENTAGON3;
				flag = 1;
			}
			break;
		default:   /* the diamond */
			shape = flag ? PENROSE_PENTAGON1 : PENROSE_PENTAGON3;
			flag = 1;
			break;
		}
		x *= TILING_PHI;
		z *= TILING_PHI;
	}
	float d;
	switch (shape) {
	case PENROSE_PENTAGON1:
		d = tiling_pentagon_dist(x);
		return fmin(fmax(1.0f / 6 - d / 6, 0.0f), 1.0f / 6 - TILING_EPS);
	case PENROSE_PENTAGON2:
	case PENROSE_PENTAGON3:
		q = tiling_penrose_fold(x, z, sqrt(x * x + z * z));
		d = tiling_pentagon_dist(q.x);
		return fmin(fmax((shape + 1.0f) / 6 - d / 6, shape / 6.0f + TILING_EPS), (shape + 1.0f) / 6 - TILING_EPS);
	case PENROSE_STAR:
		d = fabs(TILING_SIN18 * (x - TILING_PHI * a) + TILING_COS18 * z) * 5.55f * TILING_INVPHI;
		return fmin(fmax(4.0f / 6 - d / 6, 3.0f / 6 + TILING_EPS), 4.0f / 6 - TILING_EPS);
	case PENROSE_BOAT: {
		float d1 = fabs(x - TILING_INVPHI * 0.5f * TILING_COS72 / TILING_SIN36) * 5.55f * TILING_INVPHI;
		q = tiling_penrose_fold(-x, z, sqrt(x * x + z * z));
		float d2 = fabs(TILING_SIN18 * (q.x - TILING_PHI * a) + TILING_COS18 * q.y) * 5.55f * TILING_INVPHI;
		return fmin(fmax(fmax(5.0f / 6 - d1 / 6, 5.0f / 6 - d2 / 6), 4.0f / 6 + TILING_EPS), 5.0f / 6 - TILING_EPS);
	}
	default:
		d = fabs(TILING_SIN18 * (x + TILING_INVPHI * a) - TILING_COS18 * z) * 5.55f * TILING_INVPHI;
		return fmin(fmax(1.0f - d / 6, 5.0f / 6 + TILING_EPS), 1.0f - TILING_EPS);
	}
}

/* The tiling pattern's value at p: tiling number n (1 to 27, checked by the
 * host) of the x-z plane. */
static float pattern_tiling(float3 p, int n)
{
	float x = p.x, z = p.z;
	switch (n) {
	case 2: return tiling_hexagon(x, z);
	case 3: return tiling_triangle(x, z);
	case 4: return tiling_lozenge(x, z);
	case 5: return tiling_rhombus(x, z);
	case 6: return tiling_dominoes(x, z, tiling_rectangle_dx, tiling_rectangle_dz, 0xc639);
	case 7: return tiling_octa_square(x, z);
	case 8: return tiling_square_triangle(x, z);
	case 9: return tiling_hexa_triangle(x, z);
	case 10: return tiling_square_offset(x, z);
	case 11: return tiling_square_rectangle(x, z);
	case 12: return tiling_rectangle_square(x, z);
	case 13: return tiling_square_internal(x, z, 0);
	case 14: return tiling_square_internal(x, z, 1);
	case 15: return tiling_square_double(x, z);
	case 16: return tiling_hexa_square_triangle(x, z, 0);
	case 17: return tiling_hexa_square_triangle(x, z, 1);
	case 18: return tiling_dominoes(x, z, tiling_pair_dx, tiling_pair_dz, 0xcc33);
	case 19: return tiling_hexa_tri(x, z, 0);
	case 20: return tiling_hexa_tri(x, z, 1);
	case 21: return tiling_square_tri(x, z);
	case 22: return tiling_dodeca_tri(x, z);
	case 23: return tiling_dodeca_hex(x, z, 0);
	case 24: return tiling_dodeca_hex(x, z, 1);
	case 25: return tiling_penrose1(x, z);
	case 26: return tiling_penrose(x, z, 0);
	case 27: return tiling_penrose(x, z, 1);
	default: return tiling_square(x, z);
	}
}
