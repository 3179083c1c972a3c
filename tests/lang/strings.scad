// strings: escapes, str, chr, ord, len, concat, search, indexing
echo("a\"b\\c\td", ["q\"q"], "line\nbreak");
echo(str("a", 1.5, [1, "x"], true, undef), str(), str(1 / 3), str([1 : 2]));
echo(chr(65), chr([72, 105]), chr(65, 66), ord("a"), ord("é"), len("héllo"), "héllo"[1]);
echo(concat([1], [2, 3], 4, "s"), concat(), concat("a", [1]));
echo(search("a", "abcabc"), search(1, [1, 2, 1]), search([1, 2], [1, 2, 3]), search("b", ["a", "b"]));
echo(search(3, [[1, 2], [3, 4]]), search("abc", "aabbcc", 0));
echo(is_num(1), is_num(0 / 0), is_string(""), is_list([]), is_bool(false), is_undef(undef), is_undef(nope), is_function(function(x) x));
echo("\x41\u00e9\U01F600");
