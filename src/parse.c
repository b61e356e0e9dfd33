/* parse.c: runs the reentrant lexer and the pure parser over one source text. */
#include <errno.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "parse.h"
#include "parser.h"
#include "lexer.h"

/* Scans and parses text with ctx; the tree or NULL. */
static ast_node *run(struct parse_ctx *ctx, const char *text, size_t len)
{
	yyscan_t scanner;
	if (yylex_init_extra(ctx, &scanner) != 0) {
		diag_error(SRC_NOWHERE, "cannot start the scanner: %s", strerror(errno));
		return NULL;
	}
	YY_BUFFER_STATE buf = yy_scan_bytes(text, (int)len, scanner);
	int rc = yyparse(scanner, ctx);
	yy_delete_buffer(buf, scanner);
	yylex_destroy(scanner);
	if (rc != 0 || ctx->errors > 0) {
		ast_free(ctx->root);
		return NULL;
	}
	return ctx->root;
}

ast_node *parse_text(const char *name, char *text, size_t len)
{
	struct parse_ctx ctx = { .line = 1, .col = 1 };
	ctx.file = diag_add_source(name, text, len);
	int errors_before = diag_error_count();
	ast_node *root = run(&ctx, text, len);
	if (ctx.errors >= PARSE_MAX_ERRORS)
		diag_note(SRC_NOWHERE, "too many errors in '%s'; stopped after %d", name, PARSE_MAX_ERRORS);
	if (root && diag_error_count() > errors_before) {
		ast_free(root);
		return NULL;
	}
	return root;
}

ast_node *parse_macro_body(int file, size_t offset, size_t len, int line, int col)
{
	size_t all;
	const char *text = diag_source_text(file, &all);
	struct parse_ctx ctx = { .file = file, .line = line, .col = col, .offset = offset, .base = offset, .defer = 1 };
	if (!text || offset + len > all)
		return NULL;
	ast_node *root = run(&ctx, text + offset, len);
	if (root)
		return ast_block(root, KW_UNKNOWN, strdup("body"), (src_loc){ file, line, col });
	ast_node *n = ast_new(AST_MESSAGE, ctx.deferred_loc);
	n->op = 'e';
	n->str = strdup(ctx.deferred[0] ? ctx.deferred : "a syntax error");
	return n;
}

void parse_error(struct parse_ctx *ctx, src_loc loc, const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	if (!ctx->defer) {
		char msg[600];
		vsnprintf(msg, sizeof msg, fmt, ap);
		diag_error(loc, "%s", msg);
	} else if (!ctx->deferred[0]) {
		vsnprintf(ctx->deferred, sizeof ctx->deferred, fmt, ap);
		ctx->deferred_loc = loc;
	}
	va_end(ap);
	if (ctx->defer)
		ctx->errors++;
}

ast_node *parse_file(const char *path, src_loc from)
{
	size_t len;
	char *text = diag_read_file(path, &len);
	if (!text) {
		diag_error(from, "cannot read '%s': %s", path, strerror(errno));
		return NULL;
	}
	if (len > (size_t)0x7fffffff) {
		free(text);
		diag_error(from, "'%s' is larger than 2 GiB", path);
		return NULL;
	}
	return parse_text(path, text, len);
}

void parse_open(struct parse_ctx *ctx, src_loc loc, const char *what)
{
	if (ctx->n_open < PARSE_MAX_OPEN)
		ctx->open[ctx->n_open] = (struct parse_open){ loc, what };
	ctx->n_open++;
}

/* A '}' closes the innermost '{', an #end the innermost directive. One that does
 * not match leaves the record as it is, for the parser's message about it. */
void parse_close(struct parse_ctx *ctx, int directive)
{
	int before = ctx->n_open;
	if (ctx->n_open > PARSE_MAX_OPEN)
		ctx->n_open--;
	else if (ctx->n_open > 0 && (ctx->open[ctx->n_open - 1].what[0] == '{') != directive)
		ctx->n_open--;
	ctx->closed_by_last = ctx->n_open < before;
}

/* Bison does not free the symbols of a rule whose action aborts, so the list
 * is freed here when there are too many errors to go on. */
ast_node *parse_give_up(struct parse_ctx *ctx, ast_node *list)
{
	if (ctx->errors < PARSE_MAX_ERRORS)
		return list;
	ast_free(list);
	return NULL;
}

ast_node *parse_check_depth(struct parse_ctx *ctx, ast_node *n)
{
	if (n->depth > AST_MAX_DEPTH && !ctx->too_deep) {
		ctx->too_deep = 1;   /* once: the items around it are too deep as well */
		ctx->errors++;
		parse_error(ctx, n->loc, "expression nested more than %d levels deep", AST_MAX_DEPTH);
	}
	return n;
}

/* A '}' where an #end should be, or the other way round. */
static bool report_mismatch(struct parse_ctx *ctx, src_loc loc, const char *found)
{
	if (ctx->n_open == 0 || ctx->n_open > PARSE_MAX_OPEN)
		return false;
	const struct parse_open *o = &ctx->open[ctx->n_open - 1];
	bool brace = o->what[0] == '{';
	if (brace && strcmp(found, "#end") == 0) {
		parse_error(ctx, loc, "expected '}', found #end");
		if (!ctx->defer)
			diag_note(o->loc, "to close the '{' opened here");
		return true;
	}
	if (!brace && strcmp(found, "'}'") == 0) {
		parse_error(ctx, loc, "expected #end, found '}'");
		if (!ctx->defer)
			diag_note(o->loc, "to close the #%s opened here", o->what);
		return true;
	}
	return false;
}

/* The end of the file inside a block or a directive: say what is missing and
 * where the unclosed one was opened. */
static void report_unclosed(struct parse_ctx *ctx, src_loc loc)
{
	if (ctx->n_open > PARSE_MAX_OPEN) {
		parse_error(ctx, loc, "expected '}' or #end, found end of file");
		return;
	}
	const struct parse_open *o = &ctx->open[ctx->n_open - 1];
	bool brace = o->what[0] == '{';
	parse_error(ctx, loc, "expected %s, found end of file", brace ? "'}'" : "#end");
	if (ctx->defer)
		return;
	if (brace)
		diag_note(o->loc, "to close the '{' opened here");
	else
		diag_note(o->loc, "to close the #%s opened here", o->what);
}

/* A token's name as bison has it ("end of file", "'='") in the words of a
 * message: a class of tokens with the text of the one found ("identifier
 * 'Whte'"), quoted punctuation, a directive. */
static void token_words(struct parse_ctx *ctx, const char *name, bool found, char *out, size_t size)
{
	size_t n = strlen(name);
	if (n >= 2 && name[0] == '"' && name[n - 1] == '"') {
		name++;
		n -= 2;
	}
	bool is_class = name[0] != '\'' && name[0] != '#' && strncmp(name, "end of file", n) != 0;
	if (found && is_class)
		snprintf(out, size, "%.*s '%s'", (int)n, name, ctx->last_token);
	else
		snprintf(out, size, "%.*s", (int)n, name);
}

/* The tokens worth naming as expected: not the rare ones that would only confuse
 * ("'deprecated'" after #declare). */
static void expected_words(struct parse_ctx *ctx, const char *const *expected, int n, char *out, size_t size)
{
	size_t len = 0;
	int shown = 0;
	out[0] = '\0';
	for (int i = 0; i < n; i++) {
		if (strstr(expected[i], "deprecated") || strstr(expected[i], "'once'"))
			continue;
		char w[64];
		token_words(ctx, expected[i], false, w, sizeof w);
		int last = i == n - 1 || (i == n - 2 && (strstr(expected[n - 1], "deprecated") || strstr(expected[n - 1], "'once'")));
		len += (size_t)snprintf(out + len, len < size ? size - len : 0, "%s%s", shown == 0 ? "" : last ? " or " : ", ", w);
		shown++;
	}
}

void parse_report_syntax_error(struct parse_ctx *ctx, src_loc loc, const char *found, const char *const *expected,
                               int n)
{
	/* A second error on the line of the first is most often the first one's
	 * consequence, seen by the parser as it recovers. */
	if (ctx->errors > 0 && loc.line == ctx->last_error_line)
		return;
	ctx->last_error_line = loc.line;
	if (!ctx->defer)
		ctx->errors++;   /* parse_error counts the deferred ones */
	if (!expected) {
		if (strcmp(found, "memory exhausted") == 0)   /* bison's stack, YYMAXDEPTH */
			parse_error(ctx, loc, "nested too deeply: parentheses, braces and directives at most 2000 levels");
		else
			parse_error(ctx, loc, "%s", found);
		return;
	}
	if (strcmp(found, "invalid token") == 0)
		return; /* the lexer has already said what is wrong with it */
	char what[160], want[400];
	token_words(ctx, found, true, what, sizeof what);
	expected_words(ctx, expected, n, want, sizeof want);
	bool at_eof = strcmp(found, "end of file") == 0;
	if (at_eof && ctx->n_open > 0)
		report_unclosed(ctx, loc);
	else if (report_mismatch(ctx, loc, found))
		;
	else if (strcmp(found, "'}'") == 0 && ctx->n_open == 0 && !ctx->closed_by_last)
		parse_error(ctx, loc, "unmatched '}'");
	else if (strcmp(found, "#end") == 0 && ctx->n_open == 0 && !ctx->closed_by_last)
		parse_error(ctx, loc, "#end without an #if, #while, #for, #switch or #macro to close");
	else if (want[0])
		parse_error(ctx, loc, "expected %s, found %s", want, what);
	else
		parse_error(ctx, loc, "unexpected %s", what);
}
