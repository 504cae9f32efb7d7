//! The front end: source text → pest parse tree → spanned AST → validated
//! program → lowered algebraic objects. This is the only layer that knows
//! about source positions (line:column) and user-facing names; it hands the
//! algebra plain polynomials indexed by a symbol table and must not do any
//! algebra beyond building those polynomials.
