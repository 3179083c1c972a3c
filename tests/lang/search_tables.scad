// search(): number, string and list match values against tables,
// num_returns_per_match 0/1/2, index_col_num, whole-entry matches.
t = [[1, "a"], [2, "b"], [1, "c"], [[1, 2], "d"]];
echo(search(1, t));
echo(search(1, t, 0));
echo(search(1, t, 2));
echo(search([1, 2], t));
echo(search([1, 2], t, 0));
echo(search([[1, 2]], t));
echo(search([[1, 2]], t, 0, 0));
echo(search("b", t, 1, 1));
echo(search("bc", t, 0, 1));
echo(search(["a", "zz"], t, 1, 1));
echo(search(["a", "zz"], t, 0, 1));
echo(search(3, [1, 3, 3]));
echo(search([3], [1, 3, 3], 0));
echo(search(1, [[1, 2], 1], 1, 1));
echo(search("ab", "abcab", 0));
echo(search("x", "abc"));
echo(search(undef, [undef, 1]));
echo(search([], t));
echo(search(true,[true,1]));
echo(search(1,[true,1]));echo(search([true],[true,1]));echo(search(1, 5));echo(search("a", 5));echo(search(1, "a1"));
echo(search("az",[["a",1]]));
echo(search("az",[["a",1]],0));echo(search("az",[]));echo(search("",[["a",1]]));echo(search("a",[]));
