// str() of every kind of value
echo(str(1, "a", true, undef, [1, "b", [2]], [0 : 2], 1.5));
echo(str(), str(""), str(function(x) x + 1));
echo(str([]), str([[]]), str(-0), str(1e-10), str(123456789));
echo(str("a") == "a", str(1) == "1");
