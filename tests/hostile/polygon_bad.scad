polygon(points = [[0, 0]], paths = [[0, 5, -1]]);
polygon([]);
polygon([[0, 0], [0, 0], [0, 0]]);
polygon(points = [[0, 0], [1, 0], [0, 1]], paths = [[]]);
polygon(points = [[0, 0], [1, 0], [0, 1]], paths = [[0, 1, 2], [2, 1e300, 0 / 0]]);
polygon(points = [1, 2, 3]);
polygon("abc");
