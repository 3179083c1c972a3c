// Strings in .csg with openscad's escapes (QuotedString)
import(file = "B-\" C-\t D-\n E-'", layer = "A:\\ B:\" C:\t D:\n E:' F:\\\\");
text("a\tb\\c\"d");
surface("a\"b.dat");
text("x", font="a\"b", direction="l\tr");
