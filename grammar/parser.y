/* parser.y: the grammar of .scn files. Every action is one constructor call; the
 * meaning of each keyword is checked by the evaluator, not here, and directives
 * become nodes the evaluator runs.
 *
 * Expressions have POV-Ray 3.7's levels. Where POV-Ray reads a float, a vector or
 * a colour (an argument, a vector component, the value of a #declare) it reads the
 * arithmetic level, sum: + - * / and the unary operators. The comparisons, & | and
 * ?: exist only inside parentheses, function arguments, an index and the
 * conditions of directives, so a '<' or '>' in an argument always starts or ends
 * a vector, as in POV-Ray. */
%define api.pure full
%define parse.error custom
%locations
%expect 0

%code requires {
#include "ast.h"
struct parse_ctx;
typedef void *yyscan_t;
}

%code {
#include <stdlib.h>
#include <string.h>
#include "parse.h"
#include "lexer.h"
#define L(yl) ((src_loc){ ctx->file, (yl).first_line, (yl).first_column })
#define YYMAXDEPTH 2000
#define CHECK_DEPTH(n) parse_check_depth(ctx, (n))
#define LIST(name, yl) ast_block(ast_new(AST_BLOCK, L(yl)), KW_UNKNOWN, strdup(name), L(yl))
#define NAMED(name, items) ast_block((items), KW_UNKNOWN, strdup(name), (items)->loc)
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
%token <kw> T_COLOR_KW "'color'"
%token <kw> T_RGB_KW "colour keyword"
%token <kw> T_COMP_KW "colour component"
%token <kw> T_FUNC_KW "function name"
%token T_TEXTURE "'texture'"
%token T_ARRAY "'array'"
%token T_FUNCTION "'function'"
%token T_DEPRECATED "'deprecated'"
%token T_ONCE "'once'"
%token T_LE "'<='"
%token T_GE "'>='"
%token T_NE "'!='"
%token D_DECLARE "#declare"
%token D_LOCAL "#local"
%token D_INCLUDE "#include"
%token D_MACRO "#macro"
%token D_END "#end"
%token D_IF "#if"
%token D_IFDEF "#ifdef"
%token D_IFNDEF "#ifndef"
%token D_ELSE "#else"
%token D_ELSEIF "#elseif"
%token D_WHILE "#while"
%token D_FOR "#for"
%token D_SWITCH "#switch"
%token D_CASE "#case"
%token D_RANGE "#range"
%token D_BREAK "#break"
%token D_UNDEF "#undef"
%token D_VERSION "#version"
%token D_DEFAULT "#default"
%token D_DEBUG "#debug"
%token D_WARNING "#warning"
%token D_ERROR "#error"
%token D_FOPEN "#fopen"
%token D_FCLOSE "#fclose"
%token D_READ "#read"
%token D_WRITE "#write"
%token <node> T_MACRO_BODY "the body of a macro"
%token T_ERROR "invalid token"

%type <node> items item block tex_block layers value directive if_tail switch_items head
%type <node> expr logic rel cexpr sum term unary postfix primary
%type <node> components args arglist arg params paramlist lvalue
%type <node> array dims init init_items function
%type <kw> decl_kw

%destructor { free($$); } <str>
%destructor { ast_free($$); } <node>

/* An expression followed by something that could continue it continues it, as in
 * POV-Ray: "translate <1,0,0> -x" is one argument, "Red filter 0.5" one colour,
 * "A[1]" an element, "M(1)" a call. LOW marks the rules that give way. */
%precedence LOW
%precedence T_COMP_KW T_TEXTURE '(' '[' '{'
%precedence '+' '-'

%%

file:
	items                         { ctx->root = $1; $1->kw = KW_FILE; }
	;

items:
	%empty                        { $$ = ast_new(AST_BLOCK, L(@$)); }
	| items item                  { $$ = ast_append($1, CHECK_DEPTH($2)); }
	| items ','                   { $$ = $1; /* commas between arguments are optional in POV-Ray */ }
	| items ';'                   { $$ = $1; /* the end of a #declare, maybe given by a macro */ }
	| items ':'                   { $$ = $1; /* polynomial { 4, xyz(2, 0, 0): 1 }: the term's number follows */ }
	| items error                 { $$ = parse_give_up(ctx, $1); if (!$$) YYABORT; }
	;

item:
	cexpr %prec LOW               { $$ = $1; }
	| block                       { $$ = $1; }
	| T_ARG_KW cexpr %prec LOW    { $$ = ast_keyword(AST_ARG, L(@1), $1, $2); }
	| T_FLAG_KW                   { $$ = ast_keyword(AST_FLAG, L(@1), $1, NULL); }
	| T_BLOCK_KW cexpr %prec LOW  { $$ = ast_keyword(AST_ARG, L(@1), $1, $2);
	                                /* interior 2, .5 of a fractal pattern */ }
	| T_ONCE                      { $$ = ast_keyword(AST_FLAG, L(@1), KW_ONCE, NULL); /* image_map { ... once } */ }
	| '[' items ']'               { $$ = $2; $$->kind = AST_ENTRY; $$->loc = L(@1); }
	| directive                   { $$ = $1; }
	;

block:
	T_BLOCK_KW '{' items '}'      { $$ = ast_block($3, $1, NULL, L(@1)); }
	| T_BLOCK_KW '{' items T_BLOCK_KW '}'
	                              { $$ = ast_block(ast_append($3, ast_keyword(AST_FLAG, L(@4), $4, NULL)), $1, NULL, L(@1));
	                                /* bounded_by { clipped_by }: the object's clip as its bound */ }
	| T_ARG_KW '{' items '}'      { $$ = ast_block($3, $1, NULL, L(@1)); }
	| T_IDENT '{' items '}'       { $$ = ast_block($3, KW_UNKNOWN, $1, L(@1));
	                                /* the evaluator says "'cylinder' is not supported yet" */ }
	| tex_block                   { $$ = $1; }
	| function                    { $$ = $1; }
	;

tex_block:
	T_TEXTURE '{' items '}'       { $$ = ast_block($3, KW_TEXTURE, NULL, L(@1)); }
	;

/* #declare T = texture { A } texture { B }: a layered texture. */
layers:
	tex_block                     { $$ = $1; }
	| layers tex_block            { $$ = ast_op(AST_BLOCK, L(@1), 0, $1, $2);
	                                $$->kw = KW_UNKNOWN; $$->str = strdup("layers"); }
	;

function:
	T_FUNCTION '{' items '}'      { $$ = ast_op(AST_FUNCTION, L(@1), 0, LIST("params", @1), NAMED("body", $3)); }
	| T_FUNCTION T_NUMBER ',' T_NUMBER '{' items '}'
	                              { $$ = ast_op(AST_FUNCTION, L(@1), 0, LIST("params", @1), NAMED("body", $6));
	                                /* a height_field's image of Width, Height pixels: the
	                                 * sizes are a third kid, "size" */
	                                ast_append($$, ast_append(ast_append(LIST("size", @2),
	                                           ast_number(L(@2), $2)), ast_number(L(@4), $4))); }
	| T_FUNCTION '(' params ')' '{' items '}'
	                              { $$ = ast_op(AST_FUNCTION, L(@1), 0, $3, NAMED("body", $6)); }
	;

/* ---- directives ---- */

directive:
	decl_kw lvalue '=' value              { $$ = ast_declare(L(@1), $1, $2, $4); $$->num = yychar == ';'; }
	| decl_kw T_DEPRECATED deprecation T_STRING lvalue '=' value
	                                      { $$ = ast_declare(L(@1), $1, $5, $7); free($4); $$->num = yychar == ';'; }
	| D_INCLUDE cexpr %prec LOW           { $$ = ast_op(AST_INCLUDE, L(@1), 0, $2, NULL); }
	| D_MACRO T_IDENT '(' params ')' T_MACRO_BODY
	                                      { $$ = ast_named(AST_MACRO, L(@1), $2, $4, $6); }
	| D_IF '(' expr ')' items if_tail     { $$ = ast_concat(ast_op(AST_IF, L(@1), 'i', $3, NAMED("then", $5)), $6); }
	| D_IF '(' expr ')' items head D_ELSE items head D_END items '}'
	                                      { $$ = ast_if_heads(L(@1), $3, NAMED("then", $5), $6, NAMED("else", $8), $9, $11); }
	| D_IFDEF '(' lvalue ')' items if_tail
	                                      { $$ = ast_concat(ast_op(AST_IF, L(@1), 'd', $3, NAMED("then", $5)), $6); }
	| D_IFNDEF '(' lvalue ')' items if_tail
	                                      { $$ = ast_concat(ast_op(AST_IF, L(@1), 'n', $3, NAMED("then", $5)), $6); }
	| D_WHILE '(' expr ')' items D_END    { $$ = ast_op(AST_WHILE, L(@1), 0, $3, NAMED("body", $5)); }
	| D_FOR '(' T_IDENT ',' expr ',' expr ')' items D_END
	                                      { $$ = ast_named(AST_FOR, L(@1), $3, $5, $7); ast_append($$, NAMED("body", $9)); }
	| D_FOR '(' T_IDENT ',' expr ',' expr ',' expr ')' items D_END
	                                      { $$ = ast_named(AST_FOR, L(@1), $3, $5, $7);
	                                        ast_append(ast_append($$, $9), NAMED("body", $11)); }
	| D_SWITCH '(' expr ')' switch_items D_END
	                                      { $$ = ast_op(AST_SWITCH, L(@1), 0, $3, $5); }
	| D_BREAK                             { $$ = ast_new(AST_BREAK, L(@1)); }
	| D_UNDEF T_IDENT                     { $$ = ast_text(AST_UNDEF, L(@1), $2); }
	| D_VERSION cexpr %prec LOW           { $$ = ast_op(AST_VERSION, L(@1), 0, $2, NULL); }
	| D_DEFAULT '{' items '}'             { $$ = $3; $$->kind = AST_DEFAULT; $$->loc = L(@1); }
	| D_DEBUG cexpr %prec LOW             { $$ = ast_op(AST_MESSAGE, L(@1), 'd', $2, NULL); }
	| D_WARNING cexpr %prec LOW           { $$ = ast_op(AST_MESSAGE, L(@1), 'w', $2, NULL); }
	| D_ERROR cexpr %prec LOW             { $$ = ast_op(AST_MESSAGE, L(@1), 'e', $2, NULL); }
	| D_FOPEN T_IDENT cexpr T_IDENT       { $$ = ast_named(AST_FILE_IO, L(@1), strdup("fopen"), ast_text(AST_IDENT, L(@2), $2), $3);
	                                        ast_append($$, ast_text(AST_IDENT, L(@4), $4)); }
	| D_FCLOSE T_IDENT                    { $$ = ast_named(AST_FILE_IO, L(@1), strdup("fclose"), ast_text(AST_IDENT, L(@2), $2), NULL); }
	| D_READ '(' items ')'                { $$ = ast_concat(ast_named(AST_FILE_IO, L(@1), strdup("read"), NULL, NULL), $3); }
	| D_WRITE '(' items ')'               { $$ = ast_concat(ast_named(AST_FILE_IO, L(@1), strdup("write"), NULL, NULL), $3); }
	;

/* The opening of a block, when an #if chooses between two (merge or union). */
head:
	T_BLOCK_KW '{'                { $$ = ast_block(ast_new(AST_BLOCK, L(@1)), $1, NULL, L(@1)); }
	| T_ARG_KW '{'                { $$ = ast_block(ast_new(AST_BLOCK, L(@1)), $1, NULL, L(@1)); }
	| T_IDENT '{'                 { $$ = ast_block(ast_new(AST_BLOCK, L(@1)), KW_UNKNOWN, $1, L(@1)); }
	| T_TEXTURE '{'               { $$ = ast_block(ast_new(AST_BLOCK, L(@1)), KW_TEXTURE, NULL, L(@1)); }
	;

decl_kw:
	D_DECLARE                     { $$ = 'd'; }
	| D_LOCAL                     { $$ = 'l'; }
	;

/* #declare deprecated [once] "Message" Name = ...: the message is not shown. */
deprecation:
	%empty
	| T_ONCE
	;

lvalue:
	T_IDENT                       { $$ = ast_text(AST_IDENT, L(@1), $1); }
	| lvalue '[' expr ']'         { $$ = ast_op(AST_INDEX, L(@2), 0, $1, $3); }
	;

value:
	cexpr %prec LOW               { $$ = $1; }
	| T_BLOCK_KW '{' items '}'    { $$ = ast_block($3, $1, NULL, L(@1)); }
	| T_ARG_KW '{' items '}'      { $$ = ast_block($3, $1, NULL, L(@1)); }
	| T_IDENT '{' items '}'       { $$ = ast_block($3, KW_UNKNOWN, $1, L(@1)); }
	| layers %prec LOW            { $$ = $1; }
	| function                    { $$ = $1; }
	| array                       { $$ = $1; }
	| D_INCLUDE cexpr %prec LOW   { $$ = ast_op(AST_INCLUDE, L(@1), 0, $2, NULL);
	                                /* #declare M = #include "mesh.inc": the file's one value */ }
	| D_IF '(' expr ')' items if_tail
	                              { $$ = ast_concat(ast_op(AST_IFEXPR, L(@1), 'i', $3, NAMED("then", $5)), $6);
	                                /* #declare S = #if (C) sphere {...} #else box {...} #end */ }
	| D_IFDEF '(' lvalue ')' items if_tail
	                              { $$ = ast_concat(ast_op(AST_IFEXPR, L(@1), 'd', $3, NAMED("then", $5)), $6); }
	| D_IFNDEF '(' lvalue ')' items if_tail
	                              { $$ = ast_concat(ast_op(AST_IFEXPR, L(@1), 'n', $3, NAMED("then", $5)), $6); }
	;

if_tail:
	D_END                         { $$ = ast_new(AST_BLOCK, L(@1)); }
	| D_ELSE items D_END          { $$ = ast_append(ast_new(AST_BLOCK, L(@1)),
	                                                ast_block($2, KW_UNKNOWN, strdup("else"), L(@1))); }
	| D_ELSEIF '(' expr ')' items if_tail
	                              { $$ = ast_concat(ast_op(AST_BLOCK, L(@1), 0, $3, NAMED("then", $5)), $6); }
	;

switch_items:
	%empty                        { $$ = ast_block(ast_new(AST_BLOCK, L(@$)), KW_UNKNOWN, strdup("body"), L(@$)); }
	| switch_items item           { $$ = ast_append($1, CHECK_DEPTH($2)); }
	| switch_items ','            { $$ = $1; }
	| switch_items ';'            { $$ = $1; }
	| switch_items error          { $$ = parse_give_up(ctx, $1); if (!$$) YYABORT; }
	| switch_items D_CASE '(' expr ')'
	                              { $$ = ast_append($1, ast_op(AST_CASE, L(@2), 0, $4, NULL)); }
	| switch_items D_RANGE '(' expr ',' expr ')'
	                              { $$ = ast_append($1, ast_op(AST_RANGE, L(@2), 0, $4, $6)); }
	| switch_items D_ELSE         { $$ = ast_append($1, ast_new(AST_ELSE, L(@2))); }
	;

params:
	%empty                        { $$ = LIST("params", @$); }
	| paramlist                   { $$ = $1; }
	;

paramlist:
	T_IDENT                       { $$ = ast_append(LIST("params", @1), ast_text(AST_IDENT, L(@1), $1)); }
	| paramlist ',' T_IDENT       { $$ = ast_append($1, ast_text(AST_IDENT, L(@3), $3)); }
	;

/* ---- arrays ---- */

array:
	T_ARRAY dims %prec LOW        { $$ = ast_op(AST_ARRAY, L(@1), 0, $2, NULL); }
	| T_ARRAY dims init           { $$ = ast_op(AST_ARRAY, L(@1), 0, $2, $3); }
	;

dims:
	'[' expr ']'                  { $$ = ast_append(LIST("dims", @1), $2); }
	| dims '[' expr ']'           { $$ = ast_append($1, $3); }
	;

init:
	'{' init_items '}'            { $$ = $2; $$->loc = L(@1); }
	;

init_items:
	%empty                        { $$ = ast_new(AST_INIT, L(@$)); }
	| init_items cexpr %prec LOW  { $$ = ast_append($1, $2); }
	| init_items block            { $$ = ast_append($1, $2); }
	| init_items init             { $$ = ast_append($1, $2); }
	| init_items ','              { $$ = $1; }
	;

/* ---- expressions ---- */

expr:
	logic                         { $$ = $1; }
	| logic '?' expr ':' expr     { $$ = ast_op3(AST_COND, L(@2), 0, $1, $3, $5); }
	;

logic:
	rel                           { $$ = $1; }
	| logic '&' rel               { $$ = ast_op(AST_BINARY, L(@2), '&', $1, $3); }
	| logic '|' rel               { $$ = ast_op(AST_BINARY, L(@2), '|', $1, $3); }
	;

rel:
	cexpr                         { $$ = $1; }
	| rel '<' cexpr               { $$ = ast_op(AST_BINARY, L(@2), '<', $1, $3); }
	| rel '>' cexpr               { $$ = ast_op(AST_BINARY, L(@2), '>', $1, $3); }
	| rel '=' cexpr               { $$ = ast_op(AST_BINARY, L(@2), '=', $1, $3); }
	| rel T_LE cexpr              { $$ = ast_op(AST_BINARY, L(@2), OP_LE, $1, $3); }
	| rel T_GE cexpr              { $$ = ast_op(AST_BINARY, L(@2), OP_GE, $1, $3); }
	| rel T_NE cexpr              { $$ = ast_op(AST_BINARY, L(@2), OP_NE, $1, $3); }
	;

/* A colour: "color X" marks X as a colour; "rgb X" and the others take the sum
 * after them; "red 1 green 0.5" and "Red filter 0.5" set components. */
cexpr:
	sum %prec LOW                 { $$ = $1; }
	| T_COLOR_KW cexpr %prec LOW  { $$ = ast_keyword(AST_COLOR, L(@1), $1, $2); }
	| T_RGB_KW sum %prec LOW      { $$ = ast_keyword(AST_COLOR, L(@1), $1, $2); }
	| T_COMP_KW sum %prec LOW     { $$ = ast_keyword(AST_COLOR, L(@1), $1, $2); }
	| cexpr T_COMP_KW sum %prec LOW
	                              { $$ = ast_keyword(AST_COLOR, L(@2), $2, $1); ast_append($$, $3); }
	;

sum:
	term                          { $$ = $1; }
	| sum '+' term                { $$ = ast_op(AST_BINARY, L(@2), '+', $1, $3); }
	| sum '-' term                { $$ = ast_op(AST_BINARY, L(@2), '-', $1, $3); }
	;

term:
	unary                         { $$ = $1; }
	| term '*' unary              { $$ = ast_op(AST_BINARY, L(@2), '*', $1, $3); }
	| term '/' unary              { $$ = ast_op(AST_BINARY, L(@2), '/', $1, $3); }
	;

unary:
	postfix %prec LOW             { $$ = $1; }
	| '-' unary                   { $$ = ast_op(AST_UNARY, L(@1), '-', $2, NULL); }
	| '+' unary                   { $$ = ast_op(AST_UNARY, L(@1), '+', $2, NULL); }
	| '!' unary                   { $$ = ast_op(AST_UNARY, L(@1), '!', $2, NULL); }
	;

postfix:
	primary                       { $$ = $1; }
	| postfix '.' T_IDENT         { $$ = ast_named(AST_MEMBER, L(@2), $3, $1, NULL); }
	| postfix '.' T_COMP_KW       { $$ = ast_named(AST_MEMBER, L(@2), strdup(ast_keyword_name($3)), $1, NULL); }
	| postfix '[' expr ']'        { $$ = ast_op(AST_INDEX, L(@2), 0, $1, $3); }
	;

primary:
	T_NUMBER                      { $$ = ast_number(L(@1), $1); }
	| T_STRING                    { $$ = ast_text(AST_STRING, L(@1), $1); }
	| T_IDENT %prec LOW           { $$ = ast_text(AST_IDENT, L(@1), $1); }
	| T_IDENT '(' args ')'        { $$ = ast_concat(ast_text(AST_CALL, L(@1), $1), $3); }
	| T_FUNC_KW '(' args ')'      { $$ = ast_concat(ast_keyword(AST_FUNC, L(@1), $1, NULL), $3); }
	| '<' components '>'          { $$ = $2; $$->loc = L(@1); }
	| '<' components ',' '>'      { $$ = $2; $$->loc = L(@1); /* POV-Ray allows <1, 2, 3,> */ }
	| '(' expr ')'                { $$ = $2; }
	| '(' D_IF '(' expr ')' items if_tail ')'
	                              { $$ = ast_concat(ast_op(AST_IFEXPR, L(@2), 'i', $4, NAMED("then", $6)), $7); }
	;

/* POV-Ray's commas between components are optional too: <1 2 3>, but <1 -2> is <-1>. */
components:
	sum %prec LOW                 { $$ = ast_op(AST_VECTOR, L(@1), 0, $1, NULL); }
	| components ',' sum %prec LOW
	                              { $$ = ast_append($1, $3); }
	| components sum %prec LOW    { $$ = ast_append($1, $2); }
	;

args:
	%empty                        { $$ = ast_new(AST_BLOCK, L(@$)); }
	| arglist                     { $$ = $1; }
	;

arglist:
	arg                           { $$ = ast_append(ast_new(AST_BLOCK, L(@1)), $1); }
	| arglist ',' arg             { $$ = ast_append($1, $3); }
	;

arg:
	expr                          { $$ = $1; }
	| T_BLOCK_KW '{' items '}'    { $$ = ast_block($3, $1, NULL, L(@1)); }
	| T_ARG_KW '{' items '}'      { $$ = ast_block($3, $1, NULL, L(@1)); }
	| T_IDENT '{' items '}'       { $$ = ast_block($3, KW_UNKNOWN, $1, L(@1)); }
	| tex_block                   { $$ = $1; }
	| function                    { $$ = $1; }
	;

%%

static void yyerror(YYLTYPE *loc, yyscan_t scanner, struct parse_ctx *ctx, const char *msg)
{
	(void)scanner;
	parse_report_syntax_error(ctx, L(*loc), msg, NULL, 0);
}

/* "expected X or Y, found Z", from the token names: parse.c words it. */
static int yyreport_syntax_error(const yypcontext_t *yyctx, yyscan_t scanner, struct parse_ctx *ctx)
{
	(void)scanner;
	yysymbol_kind_t expected[PARSE_MAX_EXPECTED];
	int n = yypcontext_expected_tokens(yyctx, expected, PARSE_MAX_EXPECTED);
	const char *names[PARSE_MAX_EXPECTED];
	for (int i = 0; i < n; i++)
		names[i] = yysymbol_name(expected[i]);
	parse_report_syntax_error(ctx, L(*yypcontext_location(yyctx)), yysymbol_name(yypcontext_token(yyctx)),
	                          names, n);
	return 0;
}
