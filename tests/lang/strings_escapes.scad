// string escapes
echo("tab\there", "nl\nx", "quote\"q", "back\\slash");
echo("\x41\x42\x7e", "\u00e9\u4e2d", "\U01F600", "\u20AC");
echo(len("\u00e9"), len("\U01F600"), len("a\tb"));
echo(str("a", "\x20", "b"));
echo("\q \z", "unknown escapes");
echo(ord("\t"), ord("\n"), chr(10) == "\n");
// \u0000, a surrogate and a number past U+10FFFF are spaces in 2021.01
echo(str("[", "\uD800", "|", "\uDFFF", "|", "\U110000", "|", "\UFFFFFF", "|", "\U10FFFF", "]"));
