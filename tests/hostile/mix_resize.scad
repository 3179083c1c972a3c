resize([1, 2, 3]) square();
resize([0, 0]) cube();
resize([1]) circle();
