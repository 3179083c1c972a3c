// Builtin functions read their arguments as openscad 2021.01 does: only
// those they need, in their order, with its warnings (issue 18)
echo(sin(1, u1), sin(u2), atan2("a", u3), pow(1));
echo(norm(), norm([1, 2], 3), norm("x"), norm([1, "a"]), norm([3, 4]));
echo(cross([1, 2], [3, 4]), cross([1, 2, 3]), cross(1, [1]), cross([1, 2, 3], [1, 2]), cross([1, 2, 0/0], [1, 2, 3]), cross([1, 1/0, 0], [1, 2, 3]), cross([1, "a", 3], [1, 2, 3]), cross([1, 2, 3], [4, 5, 6]), cross([1, "a"], [3, 4]));
echo(ord(), ord("a", "b"), ord(5), ord(""), ord("é"), ord([1]));
echo(lookup(1), lookup(u4, [[0, 1]]), lookup(1/0, [[0, 1]]), lookup(0.5, [[0, 1], [1, 3]]));
echo(log(100), log(2, 8), log("a"), log(2, "b"), log(1, 2, 3), log(7));
echo(min(), min([]), min([3, 1, "a"]), min(3, "a", u5), min(u6, 1), min([[1], [0]]), max(4, 1, 9), min(5));
echo(parent_module(1, 2), version_num([2020, 12, 5]), version_num([1, 2]), version_num("x"), version());
echo(len(), len(1, 2), len(5), len("héllo"));
echo(rands(u7, 1, 1));
