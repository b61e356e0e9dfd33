// Pattern pigments: each becomes a pattern pigment of the scene (the
// "pigment N" lines of patterns.pov.scene: kind, parameters, wave, noise
// generator, frequency, phase, warps, its transform and its map) that the
// kernels evaluate at each point, and keeps its average colour for what needs
// one colour. Those averages, by hand, over 0 to 1, a map being constant
// before its first entry and after its last and linear between:
//  checker red, blue: <0.5, 0, 0.5>;
//  [0 rgb 0] [1 rgb 1]: 0.5;
//  [0.25 rgb 0] [0.75 rgb 1]: 0 * 0.25 + 0.5 * 0.5 + 1 * 0.25 = 0.5;
//  [0 rgb 1] [0.5 rgb 1] [0.5 rgb 0] [1 rgb 0]: 0.5;
//  the old form [0, 0.5 rgb 1 rgb 0]: a ramp from 1 to 0 over 0 to 0.5, then 0:
//    0.25;
//  bozo without a map: 0.5 (its map is POV-Ray's default one);
//  a declared pattern pigment with a colour_map after it takes the map's
//    average: <0.5, 0, 0.5>;
//  a texture_map: a pattern of whole textures ("texture_map N", its entries
//    the "texture N" lines), the average pigment (0.5) and the first
//    texture's finish for what needs one texture;
//  [0.0 blue 0.4] [1 red 1 green 0.5] (a value, then a colour of components):
//    <0.5, 0.25, 0.2>;
//  average, whose values are weights: [1 rgb x] [3 rgb z] -> <0.25, 0, 0.75>,
//    and without a warning, since that is what POV-Ray renders;
//  normal { bumps 0.5 }: a normal pattern ("normal N" and its pigment line).
#version 3.7;
global_settings { assumed_gamma 1 }
sphere { 0, 1 pigment { checker rgb <1, 0, 0>, rgb <0, 0, 1> scale 0.2 } }
sphere { 0, 1 pigment { gradient y color_map { [0 rgb 0] [1 rgb 1] } turbulence 0.5 } }
sphere { 0, 1 pigment { marble color_map { [0.25 rgb 0] [0.75 rgb 1] } } }
sphere { 0, 1 pigment { marble color_map { [0 rgb 1] [0.5 rgb 1] [0.5 rgb 0] [1 rgb 0] } } }
sphere { 0, 1 pigment { marble color_map { [0, 0.5 rgb 1 rgb 0] } } }
sphere { 0, 1 pigment { bozo } }
#declare P = pigment { wood }
sphere { 0, 1 pigment { P color_map { [0 rgb <1, 0, 0>] [1 rgb <0, 0, 1>] } } }
sphere { 0, 1 texture { gradient x texture_map { [0 pigment { rgb 1 } finish { phong 1 }]
                                                 [1 pigment { rgb 0 }] } } }
sphere { 0, 1 normal { bumps 0.5 } }
sphere { 0, 1 pigment { bozo color_map { [0.0 blue 0.4] [1 red 1 green 0.5] } } }
sphere { 0, 1 pigment { average pigment_map { [1 rgb x] [3 rgb z] } } }
