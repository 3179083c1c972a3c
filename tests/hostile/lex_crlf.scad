cube();
sphere(2);echo("ab");
