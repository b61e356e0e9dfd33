/* eval_irid.c: POV-Ray's thin-film iridescence, irid { } in a finish and
 * irid_wavelength in global_settings. Neither word is a keyword of the
 * grammar (POV-Ray has them only there), so both are read here from the
 * identifiers and expressions the parser made of them. */
#include <string.h>

#include "eval_int.h"

/* The word an item names, when it is an undeclared identifier spelt so. */
static bool is_word(struct eval *e, const ast_node *n, const char *word)
{
	return n->kind == AST_IDENT && strcmp(n->str, word) == 0 && !eval_lookup(e, word);
}

static int float_of(struct eval *e, const ast_node *n, float *out)
{
	double f;
	if (eval_expect_float(e, n, &f))
		return -1;
	*out = (float)f;
	return 0;
}

/* thickness T: the grammar makes "thickness -0.5" one difference, and
 * "thickness 0.5" the word and the number. 1 when item is no thickness. */
static int thickness(struct eval *e, struct cursor *c, const ast_node *item, float *out)
{
	if (item->kind == AST_BINARY && (item->op == '-' || item->op == '+') && is_word(e, item->kids[0], AST_WORD_THICKNESS)) {
		if (float_of(e, item->kids[1], out))
			return -1;
		if (item->op == '-')
			*out = -*out;
		return 0;
	}
	if (!is_word(e, item, AST_WORD_THICKNESS))
		return 1;
	int err = 0;
	const ast_node *v = eval_next_expr(c, &err);
	if (!v) {
		if (!err)
			eval_error(e, item->loc, "'thickness' needs a value");
		return -1;
	}
	return float_of(e, v, out);
}

static bool thickness_word(struct eval *e, const ast_node *n)
{
	return is_word(e, n, AST_WORD_THICKNESS) || (n->kind == AST_BINARY && is_word(e, n->kids[0], AST_WORD_THICKNESS));
}

/* irid { Amount [thickness T] [turbulence T] }: POV-Ray reads the first
 * component of a vector turbulence; a negative thickness is a thin film all
 * the same (the phase is a cosine), as POV-Ray renders it. */
int eval_irid(struct eval *e, const ast_node *b, scene_material *m)
{
	struct cursor c;
	int err = 0, rc = 0;
	bool first = true;
	const ast_node *item;
	eval_cursor_init(&c, e, b);
	while (rc == 0 && (item = eval_next(&c, &err)) != NULL) {
		if (first) {
			first = false;
			if (!AST_IS_EXPRESSION(item->kind) || eval_pov_word_item(e, item) || thickness_word(e, item)) {
				eval_error(e, item->loc, "irid { } begins with its amount");
				rc = -1;
			} else {
				rc = float_of(e, item, &m->irid);
			}
		} else if ((rc = thickness(e, &c, item, &m->irid_thickness)) <= 0) {
			continue;
		} else if (item->kind == AST_ARG && item->kw == KW_TURBULENCE) {
			double v[3];
			rc = eval_expect_vector(e, item->kids[0], v);
			m->irid_turbulence = (float)v[0];
		} else {
			rc = eval_not_valid(e, item, "irid { }");
		}
	}
	if (rc == 0 && !err && first) {
		eval_error(e, b->loc, "irid { } needs an amount");
		rc = -1;
	}
	eval_cursor_free(&c);
	return rc || err ? -1 : 0;
}

/* irid_wavelength COLOR: the film's wavelengths for red, green and blue, in
 * POV-Ray's units (a micrometre). */
int eval_irid_wavelength(struct eval *e, struct cursor *c, const ast_node *item)
{
	if (!is_word(e, item, AST_WORD_IRID_WAVELENGTH))
		return 1;
	int err = 0;
	double col[5];
	const ast_node *arg = eval_next_expr(c, &err);
	if (!arg) {
		if (!err)
			eval_error(e, item->loc, "'irid_wavelength' needs a colour");
		return -1;
	}
	if (eval_expect_color(e, arg, col))
		return -1;
	if (!(col[0] > 0 && col[1] > 0 && col[2] > 0)) {   /* the phase is divided by them */
		eval_error(e, arg->loc, "irid_wavelength's red, green and blue must be above 0");
		return -1;
	}
	for (int i = 0; i < 3; i++)
		e->s->irid_wavelength[i] = (float)col[i];
	return 0;
}
