module doc_root_module()
{
    linear_extrude(h = 1) square(1);
    surface("root_heights.dat");
    surface("nowhere.dat");
}
