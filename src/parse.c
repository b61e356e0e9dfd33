/* parse.c: runs the reentrant lexer and the pure parser over one source text. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "parse.h"
#include "parser.h"
#include "lexer.h"

ast_node *parse_text(const char *name, char *text, size_t len)
{
	struct parse_ctx ctx = { .line = 1, .col = 1 };
	ctx.file = diag_add_source(name, text, len);
	int errors_before = diag_error_count();

	yyscan_t scanner;
	if (yylex_init_extra(&ctx, &scanner) != 0) {
		diag_error(SRC_NOWHERE, "cannot start the scanner: %s", strerror(errno));
		return NULL;
	}
	YY_BUFFER_STATE buf = yy_scan_bytes(text, (int)len, scanner);
	int rc = yyparse(scanner, &ctx);
	yy_delete_buffer(buf, scanner);
	yylex_destroy(scanner);

	if (rc != 0 || diag_error_count() > errors_before) {
		ast_free(ctx.root);
		return NULL;
	}
	return ctx.root;
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

/* Bison says "syntax error, unexpected X, expecting A or B"; people read
 * "expected A or B, found X" faster, and the token's own text helps more than its
 * class ("found identifier 'Whte'"). */
void parse_report_syntax_error(struct parse_ctx *ctx, src_loc loc, const char *msg)
{
	static const char prefix[] = "syntax error, unexpected ";
	if (strncmp(msg, prefix, sizeof prefix - 1) != 0) {
		diag_error(loc, "%s", msg);
		return;
	}
	const char *found = msg + sizeof prefix - 1;
	const char *expecting = strstr(found, ", expecting ");
	int found_len = expecting ? (int)(expecting - found) : (int)strlen(found);
	if (strncmp(found, "invalid token", found_len) == 0)
		return; /* the lexer has already said what is wrong with it */

	char what[160];
	int is_class = found[0] != '\'' && found[0] != '"' && strncmp(found, "end of file", found_len) != 0;
	if (is_class)
		snprintf(what, sizeof what, "%.*s '%s'", found_len, found, ctx->last_token);
	else
		snprintf(what, sizeof what, "%.*s", found_len, found);

	int at_eof = strncmp(found, "end of file", found_len) == 0;
	if (at_eof && ctx->n_open > 0)
		diag_error(loc, "expected '}', found end of file");
	else if (strncmp(found, "'}'", found_len) == 0 && expecting && strstr(expecting, "end of file"))
		diag_error(loc, "unmatched '}'");
	else if (expecting)
		diag_error(loc, "expected %s, found %s", expecting + strlen(", expecting "), what);
	else
		diag_error(loc, "unexpected %s", what);

	if (at_eof && ctx->n_open > 0 && ctx->n_open <= PARSE_MAX_OPEN)
		diag_note(ctx->open[ctx->n_open - 1], "to close the '{' opened here");
}
