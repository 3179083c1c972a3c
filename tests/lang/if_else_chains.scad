// if / else if / else statements
module classify(x) {
    if (x < 0) echo("negative");
    else if (x == 0) echo("zero");
    else if (x < 10) echo("small");
    else echo("large");
}
for (x = [-5, 0, 5, 50]) classify(x);
if (undef) echo("no"); else echo("undef is false");
if ([]) echo("no"); else echo("empty list is false");
if ("0") echo("non-empty string is true");
