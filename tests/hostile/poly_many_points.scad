polyhedron(points = [for (i = [0:199999]) [i % 7, i % 11, i % 13]],
           faces = [for (i = [0:3:199990]) [i, i + 1, i + 2]]);
