/* ast.h: the syntax tree the parser builds and the evaluator walks.
 *
 * The tree is generic: a block is a keyword with a list of items, an item is an
 * expression, a block, a keyword with one argument, a flag or a directive. Which
 * items a block accepts is the evaluator's business (it knows the types), so the
 * grammar stays small and conflict-free and errors say "'location' is not valid in
 * a sphere" rather than "syntax error". Every node carries its source location. */
#ifndef ECLAT_AST_H
#define ECLAT_AST_H

#include <stdio.h>

#include "diag.h"

/* Keyword classes decide the grammar's shape around a keyword. */
enum kw_class {
	KWC_BLOCK,  /* KW { ITEMS }      sphere { <0,0,0>, 1 } */
	KWC_ARG,    /* KW EXPRESSION     translate <1,0,0> */
	KWC_FLAG,   /* KW                no_shadow */
	KWC_COLOR,  /* KW EXPRESSION, a colour value: color rgb <1,0,0> */
};

/* Every keyword the lexer knows. ORDER: alphabetical within each class is not
 * required; the lexer looks names up in this table. */
#define AST_KEYWORDS(X) \
	X(BACKGROUND, "background", BLOCK) \
	X(CAMERA, "camera", BLOCK) \
	X(FINISH, "finish", BLOCK) \
	X(GLOBAL_SETTINGS, "global_settings", BLOCK) \
	X(LIGHT_SOURCE, "light_source", BLOCK) \
	X(OBJECT, "object", BLOCK) \
	X(PIGMENT, "pigment", BLOCK) \
	X(SPHERE, "sphere", BLOCK) \
	X(TEXTURE, "texture", BLOCK) \
	X(TRIANGLE, "triangle", BLOCK) \
	X(UNION, "union", BLOCK) \
	X(AMBIENT, "ambient", ARG) \
	X(ANGLE, "angle", ARG) \
	X(DIFFUSE, "diffuse", ARG) \
	X(DIRECTION, "direction", ARG) \
	X(EMISSION, "emission", ARG) \
	X(LOCATION, "location", ARG) \
	X(LOOK_AT, "look_at", ARG) \
	X(MAX_TRACE_LEVEL, "max_trace_level", ARG) \
	X(RIGHT, "right", ARG) \
	X(ROTATE, "rotate", ARG) \
	X(SCALE, "scale", ARG) \
	X(SKY, "sky", ARG) \
	X(TRANSLATE, "translate", ARG) \
	X(UP, "up", ARG) \
	X(PERSPECTIVE, "perspective", FLAG) \
	X(COLOR, "color", COLOR) \
	X(COLOUR, "colour", COLOR) \
	X(RGB, "rgb", COLOR) \
	X(RGBF, "rgbf", COLOR) \
	X(RGBFT, "rgbft", COLOR) \
	X(RGBT, "rgbt", COLOR)

enum ast_keyword {
	KW_UNKNOWN = -2, /* NAME { ... } with a NAME that is no keyword: str holds it */
	KW_FILE = -1,    /* the block that holds a whole file */
#define X(id, name, cls) KW_##id,
	AST_KEYWORDS(X)
#undef X
	KW_COUNT
};

typedef enum {
	AST_NUMBER,   /* num */
	AST_STRING,   /* str */
	AST_IDENT,    /* str */
	AST_VECTOR,   /* kids: 2 to 5 components */
	AST_BINARY,   /* op, kids: left right */
	AST_UNARY,    /* op, kids: operand */
	AST_COLOR,    /* kw, kids: operand */
	AST_BLOCK,    /* kw, kids: items */
	AST_ARG,      /* kw, kids: argument */
	AST_FLAG,     /* kw */
	AST_DECLARE,  /* str = name, op = 'd' (#declare) or 'l' (#local), kids: value */
	AST_INCLUDE,  /* kids: file name expression */
} ast_kind;

typedef struct ast_node {
	ast_kind kind;
	src_loc loc;
	int kw;      /* enum ast_keyword */
	int op;      /* operator character */
	double num;
	char *str;
	struct ast_node **kids;
	int n_kids, cap_kids;
} ast_node;

/* Keyword table look-ups. */
int ast_keyword_lookup(const char *name, enum kw_class *cls); /* -1 when not a keyword */
const char *ast_keyword_name(int kw);

/* Constructors, one per grammar action. They take ownership of their arguments and
 * exit with a message on out of memory (a parser cannot recover from that). */
ast_node *ast_new(ast_kind kind, src_loc loc);
ast_node *ast_number(src_loc loc, double v);
ast_node *ast_text(ast_kind kind, src_loc loc, char *s);
ast_node *ast_op(ast_kind kind, src_loc loc, int op, ast_node *a, ast_node *b);
ast_node *ast_keyword(ast_kind kind, src_loc loc, int kw, ast_node *arg);
ast_node *ast_declare(src_loc loc, int op, char *name, ast_node *value);
ast_node *ast_append(ast_node *list, ast_node *kid);

void ast_free(ast_node *n);
/* Writes the tree as S-expressions with locations, for --dump-ast and golden tests. */
void ast_dump(const ast_node *n, FILE *out);

#endif
