// is_undef is_num is_bool is_string is_list is_function
vals = [undef, 1, 0/0, 1/0, true, "s", [], [1], function(x) x];
echo([for (v = vals) is_undef(v)]);
echo([for (v = vals) is_num(v)]);
echo([for (v = vals) is_bool(v)]);
echo([for (v = vals) is_string(v)]);
echo([for (v = vals) is_list(v)]);
echo([for (v = vals) is_function(v)]);
echo(is_undef(never_defined), is_num(), is_list([0 : 2]));
