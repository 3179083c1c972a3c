echo(lookup(0 / 0, [[0, 1], [1, 2]]), lookup(1, []), lookup(1, [[1 / 0, 0]]), lookup("a", "b"));
