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

/* 6: 2 by 1 rectangles in a woven pattern of period 4: those along z take
 * [0.5, 1], those along x [0, 0.5]. The cell's sixteen unit squares each
 * name their rectangle's reference point. */
static float tiling_rectangle(float x, float z)
{
	/* per unit square (x + 4 z): the shift to the rectangle's reference, and 1
	 * for a rectangle along z */
	const float shift_x[16] = { 0, 2, 2, 3, 0, 1, 3, 3, 0, 1, 2, 4, 1, 1, 2, 3 };
	const float shift_z[16] = { 1, 0, 0, 0, 1, 2, 1, 1, 2, 2, 3, 2, 3, 3, 3, 4 };
	const int along_z = 0xc639;   /* bits: squares 0, 3, 4, 5, 9, 10, 14, 15 */
	x = tiling_wrap(x, 4.0f);
	z = tiling_wrap(z, 4.0f);
	int cell = min((int)x, 3) + 4 * min((int)z, 3);
	x -= shift_x[cell];
	z -= shift_z[cell];
	if (along_z >> cell & 1)
		return fabs(0.5f * tiling_long_z(x, z) + 0.5f);
	return fabs(0.5f * tiling_long_x(x, z));
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
	case 6: return tiling_rectangle(x, z);
	case 7: return tiling_octa_square(x, z);
	case 8: return tiling_square_triangle(x, z);
	case 9: return tiling_hexa_triangle(x, z);
	case 10: return tiling_square_offset(x, z);
	case 11: return tiling_square_rectangle(x, z);
	case 12: return tiling_rectangle_square(x, z);
	default: return tiling_square(x, z);
	}
}
