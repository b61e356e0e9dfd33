/* parser.y: the grammar of .scn files. Every action is one constructor call; the
 * meaning of each keyword is checked by the evaluator, not here. */
%define api.pure full
%define parse.error verbose
%locations
%expect 0

%code requires {
#include "ast.h"
struct parse_ctx;
typedef void *yyscan_t;
}

%code {
#include "parse.h"
#include "lexer.h"
#define L(yl) ((src_loc){ ctx->file, (yl).first_line, (yl).first_column })
static void yyerror(YYLTYPE *loc, yyscan_t scanner, struct parse_ctx *ctx, const char *msg);
}

%lex-param { yyscan_t scanner }
%parse-param { yyscan_t scanner } { struct parse_ctx *ctx }

%union {
	double num;
	char *str;
	int kw;
	ast_node *node;
}

%token T_END 0 "end of file"
%token <num> T_NUMBER "number"
%token <str> T_STRING "string"
%token <str> T_IDENT "identifier"
%token <kw> T_BLOCK_KW "object keyword"
%token <kw> T_ARG_KW "keyword"
%token <kw> T_FLAG_KW "flag keyword"
%token <kw> T_COLOR_KW "colour keyword"
%token T_DECLARE "#declare"
%token T_LOCAL "#local"
%token T_INCLUDE "#include"
%token T_ERROR "invalid token"

%type <node> items item block directive value expr components

%destructor { free($$); } <str>
%destructor { ast_free($$); } <node>

/* An expression followed by something that could continue it continues it, as in
 * POV-Ray: "translate <1,0,0> -x" is one argument. LOW makes that choice explicit. */
%precedence LOW
%left '+' '-'
%left '*' '/'
%precedence UNARY

%%

file:
	items                         { ctx->root = $1; $1->kw = KW_FILE; }
	;

items:
	%empty                        { $$ = ast_new(AST_BLOCK, L(@$)); }
	| items item                  { $$ = ast_append($1, $2); }
	| items ','                   { $$ = $1; /* commas between arguments are optional in POV-Ray */ }
	;

item:
	expr %prec LOW                { $$ = $1; }
	| block                       { $$ = $1; }
	| T_ARG_KW expr %prec LOW     { $$ = ast_keyword(AST_ARG, L(@1), $1, $2); }
	| T_FLAG_KW                   { $$ = ast_keyword(AST_FLAG, L(@1), $1, NULL); }
	| directive                   { $$ = $1; }
	;

block:
	T_BLOCK_KW '{' items '}'      { $$ = $3; $$->kw = $1; $$->loc = L(@1); }
	| T_IDENT '{' items '}'       { $$ = $3; $$->kw = KW_UNKNOWN; $$->str = $1; $$->loc = L(@1);
	                                /* the evaluator says "'box' is not supported yet" */ }
	;

directive:
	T_DECLARE T_IDENT '=' value opt_semi  { $$ = ast_declare(L(@1), 'd', $2, $4); }
	| T_LOCAL T_IDENT '=' value opt_semi  { $$ = ast_declare(L(@1), 'l', $2, $4); }
	| T_INCLUDE expr %prec LOW            { $$ = ast_op(AST_INCLUDE, L(@1), 0, $2, NULL); }
	;

value:
	expr %prec LOW                { $$ = $1; }
	| block                       { $$ = $1; }
	;

opt_semi:
	%empty
	| ';'
	;

expr:
	T_NUMBER                      { $$ = ast_number(L(@1), $1); }
	| T_STRING                    { $$ = ast_text(AST_STRING, L(@1), $1); }
	| T_IDENT                     { $$ = ast_text(AST_IDENT, L(@1), $1); }
	| '<' components '>'          { $$ = $2; $$->loc = L(@1); }
	| '(' expr ')'                { $$ = $2; }
	| expr '+' expr               { $$ = ast_op(AST_BINARY, L(@2), '+', $1, $3); }
	| expr '-' expr               { $$ = ast_op(AST_BINARY, L(@2), '-', $1, $3); }
	| expr '*' expr               { $$ = ast_op(AST_BINARY, L(@2), '*', $1, $3); }
	| expr '/' expr               { $$ = ast_op(AST_BINARY, L(@2), '/', $1, $3); }
	| '-' expr %prec UNARY        { $$ = ast_op(AST_UNARY, L(@1), '-', $2, NULL); }
	| '+' expr %prec UNARY        { $$ = ast_op(AST_UNARY, L(@1), '+', $2, NULL); }
	| T_COLOR_KW expr %prec LOW   { $$ = ast_keyword(AST_COLOR, L(@1), $1, $2); }
	;

components:
	expr                          { $$ = ast_op(AST_VECTOR, L(@1), 0, $1, NULL); }
	| components ',' expr         { $$ = ast_append($1, $3); }
	;

%%

static void yyerror(YYLTYPE *loc, yyscan_t scanner, struct parse_ctx *ctx, const char *msg)
{
	(void)scanner;
	parse_report_syntax_error(ctx, L(*loc), msg);
}
