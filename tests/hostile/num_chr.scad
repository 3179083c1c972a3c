echo(chr(1e300), chr(-1), chr(0 / 0), chr([1e9, 0, 55296]), chr(1 / 0));
echo(ord(""), ord("ab"), ord(1));
