/* eval_media.c: POV-Ray's media { }, read as POV-Ray 3.7's Parse_Media reads
 * it (its defaults are scene_default_media's). A media in an interior joins
 * the interior's chain (scene_media.prev); at the scene's level it joins the
 * atmosphere's. What POV-Ray refuses is an error here, with the same limits. */
#include <math.h>
#include <string.h>

#include "eval_int.h"

/* POV-Ray's emission past this is no light but a mistake: the kernels' sums
 * of it would overflow single precision into infinities and NaNs. */
#define MEDIA_MAX_COEFFICIENT 1e12

static int media_int(struct eval *e, const ast_node *n, int least, const char *what, int *out)
{
	double x;
	if (eval_expect_float(e, n, &x))
		return -1;
	if (!(x >= least) || x > 1e6) {
		eval_error(e, n->loc, "%s must be at least %d (and at most 1000000), not %g", what, least, x);
		return -1;
	}
	*out = (int)x;
	return 0;
}

/* A colour of absorption, emission or scattering: POV-Ray takes any, but a
 * negative one makes light out of nothing (or a sum that never converges). */
static int media_colour(struct eval *e, const ast_node *n, const char *what, double out[3])
{
	double c[5];
	if (eval_expect_color(e, n, c))
		return -1;
	for (int k = 0; k < 3; k++) {
		if (!(c[k] >= 0) || c[k] > MEDIA_MAX_COEFFICIENT) {
			eval_error(e, n->loc, "a media's %s must be between 0 and %g in each channel, not %g", what,
			           MEDIA_MAX_COEFFICIENT, c[k]);
			return -1;
		}
		out[k] = c[k];
	}
	return 0;
}

/* samples Min [, Max] */
static int media_samples(struct eval *e, struct cursor *c, const ast_node *item, scene_media *m)
{
	int err = 0;
	if (media_int(e, item->kids[0], 1, "a media's samples", &m->min_samples))
		return -1;
	m->max_samples = m->min_samples;
	const ast_node *max = eval_next_expr(c, &err);
	if (err || (max && media_int(e, max, 1, "a media's maximum samples", &m->max_samples)))
		return -1;
	if (m->max_samples < m->min_samples) {
		eval_error(e, max->loc, "a media's maximum samples (%d) is smaller than its minimum (%d)",
		           m->max_samples, m->min_samples);
		return -1;
	}
	return 0;
}

/* scattering { Type, COLOR [eccentricity F] [extinction F] } */
static int media_scattering(struct eval *e, const ast_node *b, scene_media *m)
{
	struct cursor c;
	int err = 0, rc = 0, n = 0;
	const ast_node *item;
	double x;
	eval_cursor_init(&c, e, b);
	while (rc == 0 && (item = eval_next(&c, &err)) != NULL) {
		if (n == 0 && AST_IS_EXPRESSION(item->kind)) {
			if ((rc = eval_expect_float(e, item, &x)) == 0) {
				m->type = eval_int_of(x);
				if (m->type < SCENE_SCATTER_ISOTROPIC || m->type > SCENE_SCATTER_HG)   /* POV-Ray's isotropic */
					eval_warning(e, item->loc, "unknown scattering type %g (1 to 5); isotropic scattering "
					             "is used, as POV-Ray does", x);
			}
		} else if (n == 1 && AST_IS_EXPRESSION(item->kind)) {
			rc = media_colour(e, item, "scattering", m->scattering);
		} else if (item->kind == AST_ARG && item->kw == KW_ECCENTRICITY) {
			if (m->type != SCENE_SCATTER_HG) {
				eval_error(e, item->loc, "eccentricity needs scattering type 5 (Henyey-Greenstein)");
				rc = -1;
			} else if ((rc = eval_expect_float(e, item->kids[0], &m->eccentricity)) == 0 &&
			           !(fabs(m->eccentricity) < 1)) {
				eval_error(e, item->kids[0]->loc, "eccentricity must be between -1 and 1, not %g",
				           m->eccentricity);
				rc = -1;
			}
		} else if (item->kind == AST_ARG && item->kw == KW_EXTINCTION) {
			if ((rc = eval_expect_float(e, item->kids[0], &m->extinction)) == 0 && !(m->extinction >= 0)) {
				eval_error(e, item->kids[0]->loc, "a scattering's extinction must not be negative");
				rc = -1;
			}
		} else {
			rc = eval_not_valid(e, item, "a scattering");
		}
		n++;
	}
	eval_cursor_free(&c);
	if (rc == 0 && err == 0 && n < 2) {
		eval_error(e, b->loc, "scattering needs a type and a colour: scattering { 1, rgb 0.1 }");
		return -1;
	}
	return rc || err ? -1 : 0;
}

static int media_float(struct eval *e, const ast_node *item, scene_media *m)
{
	const ast_node *n = item->kids[0];
	switch (item->kw) {
	case KW_INTERVALS: return media_int(e, n, 1, "a media's intervals", &m->intervals);
	case KW_AA_LEVEL: return media_int(e, n, 1, "a media's aa_level", &m->aa_level);
	case KW_VARIANCE: return eval_expect_float(e, n, &m->variance);
	case KW_RATIO: return eval_expect_float(e, n, &m->ratio);
	case KW_METHOD:
		if (media_int(e, n, 1, "a media's method", &m->method))
			return -1;
		if (m->method > 3) {
			eval_error(e, n->loc, "a media's method is 1, 2 or 3, not %d", m->method);
			return -1;
		}
		return 0;
	case KW_CONFIDENCE:
		if (eval_expect_float(e, n, &m->confidence))
			return -1;
		if (!(m->confidence >= 0 && m->confidence < 1)) {
			eval_error(e, n->loc, "a media's confidence must be in [0, 1), not %g", m->confidence);
			return -1;
		}
		return 0;
	case KW_AA_THRESHOLD:
		if (eval_expect_float(e, n, &m->aa_threshold))
			return -1;
		if (!(m->aa_threshold > 0)) {
			eval_error(e, n->loc, "a media's aa_threshold must be greater than 0, not %g", m->aa_threshold);
			return -1;
		}
		return 0;
	case KW_ABSORPTION: return media_colour(e, n, "absorption", m->absorption);
	case KW_EMISSION: return media_colour(e, n, "emission", m->emission);
	default: return 1;
	}
}

static int media_item(struct eval *e, struct cursor *c, const ast_node *item, scene_media *m, bool first)
{
	xform t = scene_xform_identity();
	int rc = eval_transform_item(e, c, item, &t);
	if (rc > 0)   /* POV-Ray moves the densities, written before or after */
		m->xf = scene_xform_then(&m->xf, &t);
	if (rc != 0)
		return rc < 0 ? -1 : 0;
	if (AST_IS_EXPRESSION(item->kind) && first) {
		value v;
		if (eval_expr(e, item, &v))
			return -1;
		if (v.kind != V_MEDIA || v.media < 0 || v.media >= e->s->n_media) {
			eval_value_free(&v);
			return eval_not_valid(e, item, "a media");
		}
		src_loc loc = m->loc;
		*m = e->s->media[v.media];
		m->loc = loc;
		return 0;
	}
	if (item->kind == AST_ARG && item->kw == KW_SAMPLES)
		return media_samples(e, c, item, m);
	if (item->kind == AST_ARG && (rc = media_float(e, item, m)) <= 0)
		return rc;
	if (item->kind == AST_FLAG && item->kw == KW_JITTER) {   /* jitter F */
		int err = 0;
		const ast_node *x = eval_next_expr(c, &err);
		if (err || !x) {
			if (!err)
				eval_error(e, item->loc, "a media's jitter needs an amount: jitter 0.5");
			return -1;
		}
		return eval_expect_float(e, x, &m->jitter);
	}
	if (item->kind == AST_BLOCK && item->kw == KW_SCATTERING)
		return media_scattering(e, item, m);
	if (item->kind == AST_BLOCK && item->kw == KW_DENSITY)
		return eval_media_density(e, item, m);
	if (item->kind == AST_IDENT && strcmp(item->str, "collect") == 0)
		return 0;   /* photons eclat does not have */
	return eval_not_valid(e, item, "a media");
}

/* media { [MEDIA_IDENTIFIER] [intervals N] [samples Min [, Max]] [method 1 | 2 | 3]
 *         [jitter F] [aa_threshold F] [aa_level N] [absorption COLOR]
 *         [emission COLOR] [scattering { Type, COLOR [eccentricity F] [extinction F] }]
 *         [confidence F] [variance F] [ratio F] [density { ... }]... [TRANSFORMATIONS...] } */
static int media_block(struct eval *e, const ast_node *b, scene_media *out)
{
	scene_media m = scene_default_media();
	m.loc = b->loc;
	struct cursor c;
	int err = 0, rc = 0;
	bool first = true;
	const ast_node *item;
	eval_cursor_init(&c, e, b);
	while (rc == 0 && (item = eval_next(&c, &err)) != NULL) {
		rc = media_item(e, &c, item, &m, first);
		first = false;
	}
	eval_cursor_free(&c);
	if (rc || err)
		return -1;
	m.prev = -1;
	*out = m;
	return 0;
}

int eval_media_interior(struct eval *e, const ast_node *b, scene_material *m)
{
	scene_media md;
	if (media_block(e, b, &md))
		return -1;
	md.prev = m->media - 1;
	m->media = scene_add_media(e->s, &md) + 1;
	return 0;
}

/* Scene-level media: POV-Ray's atmosphere, through every hollow space. */
int eval_media_statement(struct eval *e, const ast_node *b)
{
	scene_media md;
	if (media_block(e, b, &md))
		return -1;
	md.prev = e->s->atmosphere - 1;
	e->s->atmosphere = scene_add_media(e->s, &md) + 1;
	return 0;
}

/* #declare M = media { ... } */
int eval_media_value(struct eval *e, const ast_node *b, value *out)
{
	scene_media md;
	if (media_block(e, b, &md))
		return -1;
	*out = (value){ .kind = V_MEDIA, .media = scene_add_media(e->s, &md) };
	return 0;
}
