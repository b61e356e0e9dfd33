/* ast.c: syntax tree nodes, the keyword table and the --dump-ast printer. */
#include <stdbool.h>
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

/* The table is searched by hashing once, on first use: the lexer calls this for
 * every word of every file, and the include files hold tens of thousands. */
#define KW_HASH_SIZE 1024
static short kw_hash[KW_HASH_SIZE];

static unsigned hash_name(const char *s)
{
	unsigned h = 5381;
	while (*s)
		h = h * 33 + (unsigned char)*s++;
	return h;
}

static void build_hash(void)
{
	for (int i = 0; i < KW_COUNT; i++) {
		unsigned h = hash_name(keywords[i].name) % KW_HASH_SIZE;
		while (kw_hash[h])
			h = (h + 1) % KW_HASH_SIZE;
		kw_hash[h] = (short)(i + 1);
	}
}

int ast_keyword_lookup(const char *name, enum kw_class *cls)
{
	static int built;
	if (!built) {
		build_hash();
		built = 1;
	}
	for (unsigned h = hash_name(name) % KW_HASH_SIZE; kw_hash[h]; h = (h + 1) % KW_HASH_SIZE) {
		int i = kw_hash[h] - 1;
		if (strcmp(keywords[i].name, name) == 0) {
			*cls = keywords[i].cls;
			return i;
		}
	}
	return -1;
}

const char *ast_keyword_name(int kw)
{
	return kw >= 0 && kw < KW_COUNT ? keywords[kw].name : "file";
}

enum kw_class ast_keyword_class(int kw)
{
	return kw >= 0 && kw < KW_COUNT ? keywords[kw].cls : KWC_BLOCK;
}

static void *xcalloc(size_t n, size_t size)
{
	void *p = calloc(n, size);
	if (!p) {
		fprintf(stderr, "eclat: out of memory\n");
		diag_exit(1);
	}
	return p;
}

ast_node *ast_new(ast_kind kind, src_loc loc)
{
	ast_node *n = xcalloc(1, sizeof *n);
	n->kind = kind;
	n->loc = loc;
	n->kw = KW_FILE;
	n->depth = 1;
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
			diag_exit(1);
		}
	}
	list->kids[list->n_kids++] = kid;
	if (kid->depth + 1 > list->depth)
		list->depth = kid->depth + 1;
	return list;
}

ast_node *ast_concat(ast_node *a, ast_node *b)
{
	for (int i = 0; i < b->n_kids; i++)
		ast_append(a, b->kids[i]);
	b->n_kids = 0;
	ast_free(b);
	return a;
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

ast_node *ast_op3(ast_kind kind, src_loc loc, int op, ast_node *a, ast_node *b, ast_node *c)
{
	ast_node *n = ast_op(kind, loc, op, a, b);
	if (c)
		ast_append(n, c);
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

ast_node *ast_named(ast_kind kind, src_loc loc, char *name, ast_node *a, ast_node *b)
{
	ast_node *n = ast_op(kind, loc, 0, a, b);
	n->str = name;
	return n;
}

/* target is an AST_IDENT, or AST_INDEX nodes around one: #declare A[1][2] = V
 * becomes (#declare A V 1 2). The parser sets num to 1 when a ';' follows V
 * (the token after an expression, which it has read to end the expression). */
ast_node *ast_declare(src_loc loc, int op, ast_node *target, ast_node *value)
{
	ast_node *n = ast_new(AST_DECLARE, loc);
	n->op = op;
	ast_append(n, value);
	ast_node *indices[64];
	int k = 0;
	while (target->kind == AST_INDEX) {
		if (k < 64)
			indices[k++] = target->kids[1];
		else
			ast_free(target->kids[1]);
		ast_node *base = target->kids[0];
		target->n_kids = 0;
		ast_free(target);
		target = base;
	}
	n->str = target->str;
	target->str = NULL;
	ast_free(target);
	while (k > 0)
		ast_append(n, indices[--k]);
	return n;
}

ast_node *ast_block(ast_node *items, int kw, char *name, src_loc loc)
{
	items->kw = kw;
	items->str = name;
	items->loc = loc;
	return items;
}

/* Without recursion: a tree too deep for the other stages must still be freed. */
ast_node *ast_if_heads(src_loc loc, ast_node *cond, ast_node *then, ast_node *head1, ast_node *els,
                       ast_node *head2, ast_node *body)
{
	head1->kids = body->kids;
	head1->n_kids = body->n_kids;
	head1->cap_kids = body->cap_kids;
	head1->depth = body->depth + 1;
	head2->kids = body->kids;
	head2->n_kids = body->n_kids;
	head2->depth = body->depth + 1;
	head2->op = 'B';
	body->kids = NULL;
	body->n_kids = 0;
	ast_free(body);
	ast_node *n = ast_op(AST_IF, loc, 'i', cond, ast_append(then, head1));
	return ast_append(n, ast_append(els, head2));
}

void ast_free(ast_node *n)
{
	if (!n)
		return;
	ast_node **stack = NULL;
	size_t top = 0, cap = 0;
	for (;;) {
		bool borrowed = n->kind == AST_BLOCK && n->op == 'B';
		for (int i = 0; !borrowed && i < n->n_kids; i++) {
			if (top == cap) {
				cap = cap ? 2 * cap : 64;
				stack = realloc(stack, cap * sizeof *stack);
				if (!stack) {
					fprintf(stderr, "eclat: out of memory\n");
					diag_exit(1);
				}
			}
			stack[top++] = n->kids[i];
		}
		if (!borrowed)
			free(n->kids);
		free(n->str);
		free(n);
		if (top == 0)
			break;
		n = stack[--top];
	}
	free(stack);
}

/* "+", "<=", ...: an operator as written. The buffer of a one-character operator is
 * static, so the result lasts until the next call. */
const char *ast_op_name(int op)
{
	static char one[2];
	switch (op) {
	case OP_LE: return "<=";
	case OP_GE: return ">=";
	case OP_NE: return "!=";
	default: one[0] = (char)op; return one;
	}
}

static void dump_string(const char *s, FILE *out)
{
	fputs("string \"", out);
	for (const char *c = s; *c; c++)
		fprintf(out, *c == '"' || *c == '\\' ? "\\%c" : *c == '\n' ? "\\n" : "%c", *c);
	fputc('"', out);
}

/* The head of a node's S-expression: what it is, without its kids. */
static void dump_head(const ast_node *n, FILE *out)
{
	static const char *const directive[] = {
		[AST_INCLUDE] = "#include", [AST_WHILE] = "#while", [AST_SWITCH] = "#switch",
		[AST_CASE] = "#case", [AST_RANGE] = "#range", [AST_ELSE] = "#else", [AST_BREAK] = "#break",
		[AST_VERSION] = "#version", [AST_DEFAULT] = "#default", [AST_COND] = "?:",
		[AST_VECTOR] = "vector", [AST_ENTRY] = "[]", [AST_ARRAY] = "array", [AST_INIT] = "{}",
	};
	switch (n->kind) {
	case AST_NUMBER: fprintf(out, "%.9g", n->num); break;
	case AST_STRING: dump_string(n->str, out); break;
	case AST_IDENT: fprintf(out, "ident %s", n->str); break;
	case AST_BINARY:
	case AST_UNARY: fputs(ast_op_name(n->op), out); break;
	case AST_BLOCK:
		fputs(n->kw == KW_UNKNOWN ? n->str : ast_keyword_name(n->kw), out);
		break;
	case AST_COLOR:
	case AST_ARG:
	case AST_FLAG:
	case AST_FUNC: fputs(ast_keyword_name(n->kw), out); break;
	case AST_MEMBER: fprintf(out, ".%s", n->str); break;
	case AST_INDEX: fputs("[]", out); break;
	case AST_CALL: fprintf(out, "call %s", n->str); break;
	case AST_FUNCTION: fputs("function", out); break;
	case AST_DECLARE: fprintf(out, "#%s %s", n->op == 'l' ? "local" : "declare", n->str); break;
	case AST_MACRO: fprintf(out, "#macro %s", n->str); break;
	case AST_IF: fputs(n->op == 'd' ? "#ifdef" : n->op == 'n' ? "#ifndef" : "#if", out); break;
	case AST_IFEXPR: fputs("(#if)", out); break;
	case AST_FOR: fprintf(out, "#for %s", n->str); break;
	case AST_UNDEF: fprintf(out, "#undef %s", n->str); break;
	case AST_MESSAGE: fputs(n->op == 'd' ? "#debug" : n->op == 'w' ? "#warning" : "#error", out); break;
	case AST_FILE_IO: fprintf(out, "#%s", n->str); break;
	default: fputs(directive[n->kind], out); break;
	}
}

static void dump(const ast_node *n, FILE *out, int indent)
{
	fprintf(out, "%*s(", indent, "");
	dump_head(n, out);
	fprintf(out, " @%d:%d", n->loc.line, n->loc.col);
	if (n->kind == AST_BLOCK && n->op == 'B') {
		fputs(" (the items of the block before))", out);
		return;
	}
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
