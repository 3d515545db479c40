"""The NC language front end: lexer, parser, expressions, G-group tables."""
