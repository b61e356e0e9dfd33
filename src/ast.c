/* ast.c: syntax tree nodes, the keyword table and the --dump-ast printer. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ast.h"

static const struct {
	const char *name;
	enum kw_class cls;
} keywords[KW_COUNT] = {
#define X(id, name, cls) { name, KWC_##cls },
	AST_KEYWORDS(X)
#undef X
};

int ast_keyword_lookup(const char *name, enum kw_class *cls)
{
	for (int i = 0; i < KW_COUNT; i++)
		if (strcmp(keywords[i].name, name) == 0) {
			*cls = keywords[i].cls;
			return i;
		}
	return -1;
}

const char *ast_keyword_name(int kw)
{
	return kw >= 0 && kw < KW_COUNT ? keywords[kw].name : "file";
}

static void *xcalloc(size_t n, size_t size)
{
	void *p = calloc(n, size);
	if (!p) {
		fprintf(stderr, "eclat: out of memory\n");
		exit(1);
	}
	return p;
}

ast_node *ast_new(ast_kind kind, src_loc loc)
{
	ast_node *n = xcalloc(1, sizeof *n);
	n->kind = kind;
	n->loc = loc;
	n->kw = KW_FILE;
	return n;
}

ast_node *ast_number(src_loc loc, double v)
{
	ast_node *n = ast_new(AST_NUMBER, loc);
	n->num = v;
	return n;
}

ast_node *ast_text(ast_kind kind, src_loc loc, char *s)
{
	ast_node *n = ast_new(kind, loc);
	n->str = s;
	return n;
}

ast_node *ast_append(ast_node *list, ast_node *kid)
{
	if (list->n_kids == list->cap_kids) {
		list->cap_kids = list->cap_kids ? 2 * list->cap_kids : 4;
		list->kids = realloc(list->kids, list->cap_kids * sizeof *list->kids);
		if (!list->kids) {
			fprintf(stderr, "eclat: out of memory\n");
			exit(1);
		}
	}
	list->kids[list->n_kids++] = kid;
	return list;
}

ast_node *ast_op(ast_kind kind, src_loc loc, int op, ast_node *a, ast_node *b)
{
	ast_node *n = ast_new(kind, loc);
	n->op = op;
	if (a)
		ast_append(n, a);
	if (b)
		ast_append(n, b);
	return n;
}

ast_node *ast_keyword(ast_kind kind, src_loc loc, int kw, ast_node *arg)
{
	ast_node *n = ast_new(kind, loc);
	n->kw = kw;
	if (arg)
		ast_append(n, arg);
	return n;
}

ast_node *ast_declare(src_loc loc, int op, char *name, ast_node *value)
{
	ast_node *n = ast_op(AST_DECLARE, loc, op, value, NULL);
	n->str = name;
	return n;
}

void ast_free(ast_node *n)
{
	if (!n)
		return;
	for (int i = 0; i < n->n_kids; i++)
		ast_free(n->kids[i]);
	free(n->kids);
	free(n->str);
	free(n);
}

static void dump(const ast_node *n, FILE *out, int indent)
{
	fprintf(out, "%*s(", indent, "");
	switch (n->kind) {
	case AST_NUMBER: fprintf(out, "%.9g", n->num); break;
	case AST_STRING:
		fputs("string \"", out);
		for (const char *c = n->str; *c; c++)
			fprintf(out, *c == '"' || *c == '\\' ? "\\%c" : *c == '\n' ? "\\n" : "%c", *c);
		fputc('"', out);
		break;
	case AST_IDENT: fprintf(out, "ident %s", n->str); break;
	case AST_VECTOR: fputs("vector", out); break;
	case AST_BINARY:
	case AST_UNARY: fprintf(out, "%c", n->op); break;
	case AST_BLOCK:
		fputs(n->kw == KW_UNKNOWN ? n->str : ast_keyword_name(n->kw), out);
		break;
	case AST_COLOR:
	case AST_ARG:
	case AST_FLAG: fputs(ast_keyword_name(n->kw), out); break;
	case AST_DECLARE: fprintf(out, "#%s %s", n->op == 'l' ? "local" : "declare", n->str); break;
	case AST_INCLUDE: fputs("#include", out); break;
	}
	fprintf(out, " @%d:%d", n->loc.line, n->loc.col);
	for (int i = 0; i < n->n_kids; i++) {
		fputc('\n', out);
		dump(n->kids[i], out, indent + 2);
	}
	fputc(')', out);
}

void ast_dump(const ast_node *n, FILE *out)
{
	dump(n, out, 0);
	fputc('\n', out);
}
