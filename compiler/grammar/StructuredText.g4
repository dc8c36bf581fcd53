// IEC 61131-3 (3rd edition) Structured Text: library elements, declarations, statements and
// expressions. The grammar only recognises the shape of the text; literal values are decoded,
// ranges checked and names resolved after parsing, where the messages can be precise.
//
// Case-insensitive keywords are spelled with one fragment per letter because the Debian tool
// (ANTLR 4.7.2) predates the caseInsensitive option.
grammar StructuredText;

// ---------------------------------------------------------------------------------------------
// Library elements (IEC 61131-3 ed. 3, 6.1 and 6.8)

compilationUnit : libraryElement* EOF ;

libraryElement
    : typeDeclarationBlock
    | functionDeclaration
    | functionBlockDeclaration
    | programDeclaration
    | configurationDeclaration
    | varSection  // a CODESYS global variable list: only VAR_GLOBAL, checked when building the AST
    ;

typeDeclarationBlock : TYPE typeDeclaration+ END_TYPE ;

// The ';' after a type declaration may be left out, as CODESYS allows (`END_STRUCT END_TYPE`).
typeDeclaration : identifier ':' typeSpec (':=' declarationInitializer)? ';'? ;

functionDeclaration
    : FUNCTION identifier (':' typeSpec)? varSection* statementList END_FUNCTION ;

functionBlockDeclaration
    : FUNCTION_BLOCK identifier (EXTENDS identifier)? (IMPLEMENTS identifier (',' identifier)*)?
      varSection* statementList END_FUNCTION_BLOCK
    ;

programDeclaration : PROGRAM identifier varSection* statementList END_PROGRAM ;

// 6.8: a configuration holds either resources or the body of a single implicit resource.
configurationDeclaration
    : CONFIGURATION identifier varSection* (resourceDeclaration+ | resourceBody) END_CONFIGURATION ;

resourceDeclaration : RESOURCE identifier ON identifier resourceBody END_RESOURCE ;

resourceBody : varSection* taskDeclaration* programConfiguration* ;

// Task properties (SINGLE, INTERVAL, PRIORITY) are checked by name when the AST is built.
taskDeclaration : TASK identifier '(' taskProperty (',' taskProperty)* ')' ';' ;

taskProperty : identifier ':=' expression ;

programConfiguration
    : PROGRAM retention=(RETAIN | NON_RETAIN)? identifier (WITH identifier)? ':' identifier
      ('(' argumentList? ')')? ';'
    ;

// ---------------------------------------------------------------------------------------------
// Variables (6.5)

varSection
    : kind=(VAR | VAR_INPUT | VAR_OUTPUT | VAR_IN_OUT | VAR_TEMP | VAR_GLOBAL | VAR_EXTERNAL)
      varQualifier* varDeclaration* END_VAR                                 # variableSection
    | VAR_ACCESS accessDeclaration* END_VAR                                 # accessSection
    ;

// CODESYS's PERSISTENT (kept over a download too) is kept like RETAIN here: across power losses.
varQualifier : CONSTANT | RETAIN | NON_RETAIN | PERSISTENT ;

varDeclaration
    : identifier (',' identifier)* (AT DIRECT_ADDRESS)? ':' typeSpec
      (':=' declarationInitializer)? ';' ;

// CODESYS V2 writes an array's initial values without brackets (`:= 1, 3, 7`), only here where
// the ';' ends the list.
declarationInitializer
    : initializer                                                           # bracketedInitializer
    | arrayInitElement (',' arrayInitElement)+                              # bareArrayInitializer
    ;

accessDeclaration
    : identifier ':' accessPath ':' typeSpec direction=(READ_ONLY | READ_WRITE)? ';' ;

accessPath : DIRECT_ADDRESS | identifier ('.' identifier)* ;

initializer
    : '[' arrayInitElement (',' arrayInitElement)* ']'                      # arrayInitializer
    | '(' structInitElement (',' structInitElement)* ')'                    # structInitializer
    | expression                                                            # expressionInitializer
    ;

// `3(0)` repeats a value three times; `3()` leaves three elements at their default.
arrayInitElement : INTEGER '(' initializer? ')' | initializer ;

structInitElement : identifier ':=' initializer ;

// ---------------------------------------------------------------------------------------------
// Data types (6.4)

typeSpec
    : STRUCT varDeclaration+ END_STRUCT                                     # structType
    | ARRAY '[' arrayDimension (',' arrayDimension)* ']' OF typeSpec        # arrayType
    | REF_TO typeSpec                                                       # referenceType
    | POINTER TO typeSpec                                                   # pointerType
    // TwinCAT writes the base type after the values: `(a, b) UDINT`.
    | '(' enumValue (',' enumValue)* ')' identifier?                        # enumType
    | identifier '(' subrange ')'                                           # subrangeType
    | identifier ('[' expression ']' | '(' expression ')')                  # sizedType
    | identifier '(' enumValue (',' enumValue)* ')'                         # typedEnumType
    | identifier                                                            # namedType
    ;

arrayDimension : subrange | '*' ;

subrange : expression '..' expression ;

enumValue : identifier (':=' expression)? ;

// ---------------------------------------------------------------------------------------------
// Statements (7.3.3). An assignment or call starts with any expression, so that mistakes such as
// `x = 1;` parse and get a precise message from the AST builder instead of a syntax error. The
// ';' after END_IF and the other END_ keywords may be left out, as common tools allow.

statementList : statement* ;

statement
    : target=expression (':=' value=expression)? ';'                        # expressionStatement
    | IF expression THEN statementList elsifClause* (ELSE statementList)? END_IF ';'?  # ifStatement
    | CASE expression OF caseBranch* (ELSE statementList)? END_CASE ';'?     # caseStatement
    | FOR identifier ':=' expression TO expression (BY expression)? DO statementList END_FOR ';'?
                                                                            # forStatement
    | WHILE expression DO statementList END_WHILE ';'?                       # whileStatement
    | REPEAT statementList UNTIL expression END_REPEAT ';'?                  # repeatStatement
    | EXIT ';'                                                              # exitStatement
    | CONTINUE ';'                                                          # continueStatement
    | RETURN ';'                                                            # returnStatement
    | ';'                                                                   # emptyStatement
    ;

elsifClause : ELSIF expression THEN statementList ;

caseBranch : caseLabel (',' caseLabel)* ':' statementList ;

caseLabel : expression ('..' expression)? ;

// ---------------------------------------------------------------------------------------------
// Expressions (7.3.2, table 71): one left-recursive rule, its alternatives from the highest
// precedence to the lowest, so that an operand is one node of the parse tree, not one for each
// precedence level. Operators of one precedence apply from left to right (7.3.2), `**` too
// (`2 ** 3 ** 2` is 64), and the prefix operators bind tighter than `**` (`-2 ** 2` is 4).

expression
    : value=(INTEGER | BASED_INTEGER | REAL_LITERAL | TRUE | FALSE | NULL_REFERENCE
      | STRING_LITERAL | WSTRING_LITERAL | UNTERMINATED_STRING | TIME_LITERAL | DATE_LITERAL
      | TIME_OF_DAY_LITERAL | DATE_AND_TIME_LITERAL | TYPED_LITERAL)         # literalExpression
    | name=identifier                                                       # nameExpression
    | '(' inner=expression ')'                                              # parenthesizedExpression
    | REF '(' inner=expression ')'                                          # refExpression
    // Tables 29 and 30 list the operators MOD, AND, OR and XOR as functions as well. NOT(x)
    // needs no rule of its own: NOT applied to (x) is the same value, and a second way to read
    // it would make the parser look to the closing parenthesis at every NOT (. Its formal
    // form, NOT(IN := x) as CODESYS writes it (with EN and ENO beside it if wanted), is told
    // apart by the ':=' after the name.
    | callee=(MOD | AND | OR | XOR) '(' arguments=argumentList? ')'         # operatorCall
    | callee=NOT '(' input=formalInput (',' more+=argument)* ')'            # formalNot
    | address=DIRECT_ADDRESS                                                # directAddressExpression
    // One alternative for both, so that what follows a '.' is expected as "a name or an integer".
    | base=expression '.' (member=identifier | bit=INTEGER)                 # memberAccess
    | base=expression '[' indices+=expression (',' indices+=expression)* ']'  # indexAccess
    | base=expression '^'                                                   # dereference
    | base=expression '(' arguments=argumentList? ')'                       # callArguments
    | op=('-' | '+' | NOT) operand=expression                               # unaryExpression
    | left=expression op='**' right=expression                              # binaryExpression
    | left=expression op=('*' | '/' | MOD) right=expression                 # binaryExpression
    | left=expression op=('+' | '-') right=expression                       # binaryExpression
    | left=expression op=('<' | '>' | '<=' | '>=') right=expression         # binaryExpression
    | left=expression op=('=' | '<>') right=expression                      # binaryExpression
    | left=expression op=(AND | '&') right=expression                       # binaryExpression
    | left=expression op=XOR right=expression                               # binaryExpression
    | left=expression op=OR right=expression                                # binaryExpression
    ;

argumentList : argument (',' argument)* ;

formalInput : identifier ':=' expression ;

argument
    : identifier ':=' expression                                            # inputArgument
    | NOT? identifier '=>' expression                                       # outputArgument
    | expression                                                            # positionalArgument
    ;

// ON is a keyword only inside a RESOURCE declaration; elsewhere it is a name, as in CODESYS.
identifier : IDENTIFIER | ON ;

// ---------------------------------------------------------------------------------------------
// Lexer

BLOCK_COMMENT : '(*' (BLOCK_COMMENT | .)*? '*)' -> skip ;
C_COMMENT : '/*' (C_COMMENT | .)*? '*/' -> skip ;
LINE_COMMENT : '//' ~[\r\n]* -> skip ;
// Pragmas stay on the hidden channel: the AST builder reads the attributes above a declaration.
PRAGMA : '{' ~[}]* '}' -> channel(HIDDEN) ;
WHITESPACE : [ \t\r\n\f]+ -> skip ;
// A comment that never closes is not skipped: it reaches the parser as '(' '*' or '/' '*', a
// pair that cannot occur in ST otherwise and is reported as an unterminated comment.

TYPE : T Y P E ;
END_TYPE : E N D '_' T Y P E ;
STRUCT : S T R U C T ;
END_STRUCT : E N D '_' S T R U C T ;
ARRAY : A R R A Y ;
OF : O F ;
REF_TO : R E F '_' T O ;
REF : R E F ;
POINTER : P O I N T E R ;
TO : T O ;
VAR : V A R ;
VAR_INPUT : V A R '_' I N P U T ;
VAR_OUTPUT : V A R '_' O U T P U T ;
VAR_IN_OUT : V A R '_' I N '_' O U T ;
VAR_TEMP : V A R '_' T E M P ;
VAR_GLOBAL : V A R '_' G L O B A L ;
VAR_EXTERNAL : V A R '_' E X T E R N A L ;
VAR_ACCESS : V A R '_' A C C E S S ;
END_VAR : E N D '_' V A R ;
CONSTANT : C O N S T A N T ;
RETAIN : R E T A I N ;
NON_RETAIN : N O N '_' R E T A I N ;
PERSISTENT : P E R S I S T E N T ;
AT : A T ;
READ_ONLY : R E A D '_' O N L Y ;
READ_WRITE : R E A D '_' W R I T E ;
FUNCTION : F U N C T I O N ;
END_FUNCTION : E N D '_' F U N C T I O N ;
FUNCTION_BLOCK : F U N C T I O N '_' B L O C K ;
END_FUNCTION_BLOCK : E N D '_' F U N C T I O N '_' B L O C K ;
PROGRAM : P R O G R A M ;
END_PROGRAM : E N D '_' P R O G R A M ;
EXTENDS : E X T E N D S ;
IMPLEMENTS : I M P L E M E N T S ;
CONFIGURATION : C O N F I G U R A T I O N ;
END_CONFIGURATION : E N D '_' C O N F I G U R A T I O N ;
RESOURCE : R E S O U R C E ;
END_RESOURCE : E N D '_' R E S O U R C E ;
ON : O N ;
TASK : T A S K ;
WITH : W I T H ;
IF : I F ;
THEN : T H E N ;
ELSIF : E L S I F ;
ELSE : E L S E ;
END_IF : E N D '_' I F ;
CASE : C A S E ;
END_CASE : E N D '_' C A S E ;
FOR : F O R ;
BY : B Y ;
DO : D O ;
END_FOR : E N D '_' F O R ;
WHILE : W H I L E ;
END_WHILE : E N D '_' W H I L E ;
REPEAT : R E P E A T ;
UNTIL : U N T I L ;
END_REPEAT : E N D '_' R E P E A T ;
EXIT : E X I T ;
CONTINUE : C O N T I N U E ;
RETURN : R E T U R N ;
OR : O R ;
XOR : X O R ;
AND : A N D ;
MOD : M O D ;
NOT : N O T ;
TRUE : T R U E ;
FALSE : F A L S E ;
NULL_REFERENCE : N U L L ;

// Literals are matched loosely here and validated when decoded, so that a malformed literal gets
// a message about the literal rather than a syntax error about the characters that follow it.
TIME_LITERAL : (T | T I M E | L T | L T I M E) '#' [+-]? [0-9] [0-9a-zA-Z_.]* ;
DATE_LITERAL : (D | D A T E | L D | L D A T E) '#' [0-9] [0-9_-]* ;
TIME_OF_DAY_LITERAL
    : (T O D | T I M E '_' O F '_' D A Y | L T O D | L T I M E '_' O F '_' D A Y) '#' [0-9] [0-9:._]* ;
DATE_AND_TIME_LITERAL
    : (D T | D A T E '_' A N D '_' T I M E | L D T | L D A T E '_' A N D '_' T I M E) '#' [0-9]
      [0-9:._-]*
    ;
// INT#16#FF, REAL#1.5, BOOL#TRUE, STRING#'x', and the qualified enumeration value Color#Red.
TYPED_LITERAL
    : NAME '#' ([+-]? DIGITS ('.' DIGITS EXPONENT? | EXPONENT | '#' [0-9a-zA-Z_]+)? | NAME
      | STRING_LITERAL
      | WSTRING_LITERAL)
    ;
// `1E37` without a point is a CODESYS form; the AST builder warns about it.
REAL_LITERAL : DIGITS '.' DIGITS EXPONENT? | DIGITS EXPONENT ;
BASED_INTEGER : DIGITS '#' [0-9a-zA-Z_]+ ;
INTEGER : DIGITS ;
STRING_LITERAL : '\'' ('$' . | ~['$\r\n])* '\'' ;
WSTRING_LITERAL : '"' ('$' . | ~["$\r\n])* '"' ;
// Only wins over the rules above when the closing quote is missing on the line.
UNTERMINATED_STRING : ('\'' ('$' . | ~['$\r\n])* | '"' ('$' . | ~["$\r\n])*) ;
DIRECT_ADDRESS : '%' [IQMiqm] ([XBWDLxbwdl]? [0-9]+ ('.' [0-9]+)* | '*') ;

IDENTIFIER : NAME ;

ASSIGN : ':=' ;
OUTPUT_ASSIGN : '=>' ;
RANGE : '..' ;
POWER : '**' ;
LESS_EQUAL : '<=' ;
GREATER_EQUAL : '>=' ;
NOT_EQUAL : '<>' ;
COLON : ':' ;
SEMICOLON : ';' ;
COMMA : ',' ;
DOT : '.' ;
LEFT_PAREN : '(' ;
RIGHT_PAREN : ')' ;
LEFT_BRACKET : '[' ;
RIGHT_BRACKET : ']' ;
CARET : '^' ;
AMPERSAND : '&' ;
EQUAL : '=' ;
LESS : '<' ;
GREATER : '>' ;
PLUS : '+' ;
MINUS : '-' ;
STAR : '*' ;
SLASH : '/' ;
// Anything else reaches the parser as one token, which reports it as an unexpected character.
INVALID_CHARACTER : . ;

fragment NAME : [a-zA-Z_] [a-zA-Z_0-9]* ;
fragment DIGITS : [0-9] [0-9_]* ;
fragment EXPONENT : [eE] [+-]? DIGITS ;

fragment A : [aA] ; fragment B : [bB] ; fragment C : [cC] ; fragment D : [dD] ;
fragment E : [eE] ; fragment F : [fF] ; fragment G : [gG] ; fragment H : [hH] ;
fragment I : [iI] ; fragment J : [jJ] ; fragment K : [kK] ; fragment L : [lL] ;
fragment M : [mM] ; fragment N : [nN] ; fragment O : [oO] ; fragment P : [pP] ;
fragment Q : [qQ] ; fragment R : [rR] ; fragment S : [sS] ; fragment T : [tT] ;
fragment U : [uU] ; fragment V : [vV] ; fragment W : [wW] ; fragment X : [xX] ;
fragment Y : [yY] ; fragment Z : [zZ] ;
