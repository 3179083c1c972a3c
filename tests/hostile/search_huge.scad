x = [for (i = [0:99999]) i % 7];
echo(len(search(3, x, 0)));
echo(search("abc", "abcabcabc", 1e9));
echo(search([1, 2], [[1, 2], [2, 3]], -1, 1e300));
