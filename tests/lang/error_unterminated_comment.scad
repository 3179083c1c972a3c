// A comment never closed: openscad 2021.01 reports it at its end of file
// (the file with "\n\x03\n" appended), then a syntax error there
echo(1);
/* never closed
