// Latin-1 and UTF-8 no-break spaces are whitespace
a =Â 1; // comment
echoÂ (a);
