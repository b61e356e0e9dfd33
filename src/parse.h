/* parse.h: text to syntax tree (grammar/lexer.l and grammar/parser.y behind one call). */
#ifndef ECLAT_PARSE_H
#define ECLAT_PARSE_H

#include "ast.h"

/* Reads and parses a file. from is where it was asked for (an #include), or
 * SRC_NOWHERE for the scene file. Returns NULL after printing the errors. */
ast_node *parse_file(const char *path, src_loc from);

/* Parses text (owned by the source table from now on) registered under name. */
ast_node *parse_text(const char *name, char *text, size_t len);

/* Shared by the lexer and the parser: where each token starts, the open braces. */
#define PARSE_MAX_OPEN 64
struct parse_ctx {
	int file;
	int line, col;                    /* position of the next character */
	int comment_depth;
	src_loc comment_start;
	src_loc open[PARSE_MAX_OPEN];     /* the '{' not yet closed, innermost last */
	int n_open;
	char last_token[48];              /* text of the last token, for messages */
	ast_node *root;
};

/* Turns bison's "syntax error, unexpected X, expecting Y" into "expected Y, found X". */
void parse_report_syntax_error(struct parse_ctx *ctx, src_loc loc, const char *msg);

#endif
