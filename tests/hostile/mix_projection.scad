projection() square();
projection(cut = true) circle();
projection() projection() cube();
