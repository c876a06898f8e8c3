# host-tools/gen/scene_of.sh (sourced from the top of the tree): scene_of
# NAME prints the path of scene NAME: scenes/NAME.scn, or the scene make
# writes from its generator into build/scenes/ (city, fig9: not committed).
scene_of() {
    if [ -e "scenes/$1.scn" ]; then echo "scenes/$1.scn"; else echo "build/scenes/$1.scn"; fi
}
