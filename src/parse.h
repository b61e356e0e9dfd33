/* parse.h: text to syntax tree (grammar/lexer.l and grammar/parser.y behind one call). */
#ifndef ECLAT_PARSE_H
#define ECLAT_PARSE_H

#include "ast.h"

/* Reads and parses a file. from is where it was asked for (an #include), or
 * SRC_NOWHERE for the scene file. Returns NULL after printing the errors. */
ast_node *parse_file(const char *path, src_loc from);

/* Parses text (owned by the source table from now on) registered under name. */
ast_node *parse_text(const char *name, char *text, size_t len);

/* Parses the body of a #macro: len bytes of the registered source file from
 * offset, which starts at line, col. A syntax error in it is not reported: the
 * result is then an AST_MESSAGE node holding the error, which the evaluator
 * reports if the macro is called (POV-Ray reads a macro's body only then). */
ast_node *parse_macro_body(int file, size_t offset, size_t len, int line, int col);

/* A parse reports at most this many errors, then stops. */
#define PARSE_MAX_ERRORS 20

/* Shared by the lexer and the parser: where each token starts, and the braces
 * and directives (#if, #while, #macro...) not yet closed, for the message at an
 * unexpected end of file. */
#define PARSE_MAX_OPEN 64
struct parse_open {
	src_loc loc;
	const char *what;                 /* "{" or a directive's name: "while" */
};
struct parse_ctx {
	int file;
	int line, col;                    /* position of the next character */
	size_t offset;                    /* its byte offset in the file */
	size_t base;                      /* the offset of the text being scanned in the file */
	int comment_depth;
	src_loc comment_start;
	struct parse_open open[PARSE_MAX_OPEN]; /* innermost last */
	int n_open;
	char last_token[48];              /* text of the last token, for messages */
	int errors;                       /* syntax errors reported */
	int closed_by_last;               /* the last token was a '}' or #end that closed one */
	int last_error_line;              /* of the last syntax error reported */
	int too_deep;                     /* an item deeper than AST_MAX_DEPTH was reported */
	ast_node *root;
	/* #macro Name (Params): its body is read raw, up to the matching #end */
	int macro_head;                   /* 1 after #macro, until the ')' of its parameters */
	int body_depth;                   /* directives opened in the body */
	size_t body_start;
	int body_line, body_col;
	int comment_return;               /* the start condition a comment returns to */
	/* in a macro body: errors are kept, not printed */
	int defer;
	char deferred[300];
	src_loc deferred_loc;
};

/* An error found while scanning or parsing: printed, or kept in a macro body. */
void parse_error(struct parse_ctx *ctx, src_loc loc, const char *fmt, ...) __attribute__((format(printf, 3, 4)));

/* The lexer's bookkeeping of what is open: a '{' or a directive that #end closes. */
void parse_open(struct parse_ctx *ctx, src_loc loc, const char *what);
void parse_close(struct parse_ctx *ctx, int directive);

/* list, or NULL after freeing it when there have been too many errors. */
ast_node *parse_give_up(struct parse_ctx *ctx, ast_node *list);
/* Returns n, after an error when it is deeper than AST_MAX_DEPTH. */
ast_node *parse_check_depth(struct parse_ctx *ctx, ast_node *n);

/* Reports a syntax error at loc: found is the name of the token found, expected
 * the names of the n tokens that would have been valid (n is 0 when there are
 * too many to list). With expected NULL, found is a whole message. */
#define PARSE_MAX_EXPECTED 5
void parse_report_syntax_error(struct parse_ctx *ctx, src_loc loc, const char *found, const char *const *expected,
                               int n);

#endif
