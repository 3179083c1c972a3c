// chr and ord over ranges and edge values
echo(chr(65), chr([65, 66, 67]), chr([65 : 67]), chr(0), chr(-1), chr(1114112), chr(55296));
echo(ord("A"), ord("é"), ord("😀"), ord(""), ord(undef));
echo([for (c = "Hi!") ord(c)]);
echo(chr(65.7), chr("A"), chr([65, "x"]));
