// A $-variable cannot be called as a function in 2021.01
$f = function(x) x + 1;
echo($f(1));
f = $f;
echo(f(1));
echo($nof(1));
$n = 5;
echo($n(1));
