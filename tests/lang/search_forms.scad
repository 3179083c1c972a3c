// search(): strings, vectors, num_returns_per_match, index_col_num
echo(search("a", "abcabc"), search("a", "abcabc", 0), search("abc", "abcabc", 0));
echo(search("x", "abc"), search("", "abc"));
echo(search(3, [1, 3, 5, 3]), search(3, [1, 3, 5, 3], 0));
echo(search([3, 5], [1, 3, 5, 3]), search([3, 9], [1, 3, 5]));
data = [["a", 1], ["b", 2], ["c", 3], ["a", 4]];
echo(search("a", data), search("a", data, 0), search(["a", "c"], data, 0));
echo(search(2, data, 1, 1), search(4, data, 0, 1));
echo(search([3], [[1, 2], [3, 4], [1, 2]]));
echo(search("b", ["abc", "b", "cb"]), search(["b"], ["abc", "b", "cb"], 0));
echo(search("ab", "aabb", 2));
