// UTF-8 aware len, index, for, ord/chr, str concatenation
s = "aé€😀z";
echo(len(s), s[0], s[1], s[2], s[3], s[4], s[5]);
echo([for (c = s) ord(c)]);
echo(chr(233), chr(8364), chr(128512), chr([72, 105]), chr(72, 105));
echo(str(s, s), len(str(s, s)));
echo(search("€", s), search("é", s, 0));
echo(ord("€"), ord(""), ord("ab"), ord(5));
echo(concat("ab", "cd"), concat(["x"], "yz"));
t = str("abcdefghijk", "é", "lmnopqrstuvwxyz€0123456789😀", "ABCDEFGHIJKLMNOP");
echo(len(t), t[11], t[12], t[27], t[38], t[39], t[54]);
