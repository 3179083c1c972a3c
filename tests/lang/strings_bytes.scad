// Strings as openscad 2021.01 reads and walks them: \u0000 and \x00 are
// spaces; invalid UTF-8 (Latin-1 bytes) split by the lead byte's length;
// a zero-step range visits nothing (issue 18)
echo("\u0000\u0030\u0031 \U0000 \x00a \u00000");
s = "¤ÄÖÜß";
echo(len(s), [for (c = s) ord(c)], s[1] == "ÄÖ");
for (a = [0:0:0]) echo(zero = a);
for (a = [1:0:1]) echo(one = a);
echo([for (a = [2:0:2]) a]);
s2 = "abcdefghijklémnopqrstuvwxyz0123456789";
echo(len(s2), [for (c = s2) ord(c)][13]);
