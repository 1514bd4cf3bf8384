#!/usr/bin/env python3
"""Writes the level-art fixtures of this folder: meadow.tmx (a Tiled map), meadow.tsx and
props.tsj (its external tilesets) and canyon.ldtk (an LDtk project), over the tile art that
tools/make-tiles draws (meadow.png, cave.png, hills.png, props/*.png, copied here).
meadow.tmj is Tiled's own JSON export of meadow.tmx:

  python3 tests/level/data/art/make_fixtures.py
  QT_QPA_PLATFORM=offscreen tiled --export-map json tests/level/data/art/meadow.tmx tests/level/data/art/meadow.tmj
  QT_QPA_PLATFORM=offscreen tmxrasterizer --size 1920 tests/level/data/art/meadow.tmx tests/level/data/art/meadow.tiled.png

What the map covers (tests/level/level_art_test.cpp, tests/render/level_view_test.cpp):
  meadow.tmx   60 x 14 tiles of 32 px, pixels_per_metre 64 (a tile is 0.5 m); background colour;
               an image layer repeated along x with parallax 0.4; a tile layer behind at parallax
               0.9 with flipped and rotated tiles; the group "Terrain" (opacity 0.95) holding
               the Ground layer (collider tiles of the external meadow.tsx, a right end drawn as
               the left end flipped) and a layer of 16 px cave tiles from an embedded tileset on
               the 32 px grid; Props from an image collection (props.tsj) with a layer offset;
               a hidden layer; a tinted, translucent foreground layer (property foreground);
               the spawn.
  canyon.ldtk  one level "Canyon" (40 x 16 cells of 16 px, one cell = 0.5 m): background colour
               and image; an IntGrid layer with auto-layer tiles; a Tiles layer with flipped
               tiles; an AutoLayer behind at parallax factor 0.2 and opacity 0.6; a Foreground
               Tiles layer; the Player entity.
"""

import json
import os

HERE = os.path.dirname(os.path.abspath(__file__))
W, H = 60, 14
FLIP_H, FLIP_V, FLIP_D = 0x80000000, 0x40000000, 0x20000000

# ---- meadow.tmx ----------------------------------------------------------------------------------

# Ground height in tiles per column (the walls at both ends are stone).
def ground_height(x):
    if x == 0 or x == W - 1:
        return 9
    if 18 <= x <= 25:
        return 4
    if 34 <= x <= 37:
        return 1
    return 3


MEADOW = 1        # firstgid of meadow.tsx (32 tiles)
CAVE = 33         # firstgid of the embedded cave tileset (32 tiles)
PROPS = 65        # firstgid of props.tsj (ids 0-3)


def ground_layer():
    g = [[0] * W for _ in range(H)]
    for x in range(W):
        h = ground_height(x)
        top = H - h
        if x in (0, W - 1):
            for y in range(top, H):
                g[y][x] = MEADOW + (16 if y == top else 17)   # stone cap, stone
            continue
        left_open = ground_height(x - 1) < h
        right_open = ground_height(x + 1) < h
        for y in range(top, H):
            if y == top:
                if left_open and right_open:
                    t = MEADOW + 0
                elif left_open:
                    t = MEADOW + 1
                elif right_open:
                    t = (MEADOW + 1) | FLIP_H     # the right end: the left end mirrored
                else:
                    t = MEADOW + 0
            else:
                deep = y >= top + 2
                base = 24 if deep else 3
                if left_open and y < H - ground_height(x - 1):
                    t = MEADOW + (25 if deep else 4)
                elif right_open and y < H - ground_height(x + 1):
                    t = (MEADOW + (25 if deep else 4)) | FLIP_H
                elif not deep and (x * 7 + y) % 11 == 0:
                    t = MEADOW + 6
                else:
                    t = MEADOW + base
            g[y][x] = t
    # A plank platform over the meadow, x 44-48, 3.5 m up.
    row = H - 7
    g[row][44] = MEADOW + 8
    for x in range(45, 48):
        g[row][x] = MEADOW + 9
    g[row][48] = MEADOW + 10
    return g


def back_layer():
    g = [[0] * W for _ in range(H)]
    def put(x, t):
        g[H - ground_height(x) - 1][x] = t
    for x in (3, 12, 29, 41, 52):
        put(x, MEADOW + 13)                    # bush
    for x in (5, 6, 20, 44, 55):
        put(x, MEADOW + 14)                    # flowers
    put(7, (MEADOW + 14) | FLIP_H)             # flowers, mirrored
    for x in range(9, 12):
        put(x, MEADOW + 22)                    # fence
    put(15, MEADOW + 21)                       # signpost
    put(30, MEADOW + 20)                       # mushroom
    put(31, (MEADOW + 20) | FLIP_H)
    # Water in the pit (not solid), one tile above the pit's floor.
    for x in range(34, 38):
        g[H - 2][x] = MEADOW + 18
    # A ladder turned a quarter (diagonal + horizontal flip = 90° clockwise) lying in the grass.
    g[H - ground_height(50) - 1][50] = (MEADOW + 11) | FLIP_D | FLIP_H
    # Upside down (vertical flip): a mushroom hanging under the platform.
    g[H - 6][46] = (MEADOW + 20) | FLIP_V
    return g


def cave_layer():
    g = [[0] * W for _ in range(H)]
    for x in (22, 24):
        g[H - ground_height(x) - 1][x] = CAVE + 10   # crystals (16 px tiles on the 32 px grid)
    g[H - ground_height(23) - 1][23] = CAVE + 11     # a lantern
    return g


def props_layer():
    g = [[0] * W for _ in range(H)]
    def put(x, t):
        g[H - ground_height(x) - 1][x] = t
    put(8, PROPS + 0)      # tree (64 x 96)
    put(27, PROPS + 2)     # rock
    put(39, PROPS + 3)     # signpost
    put(57, PROPS + 1)     # bush
    return g


def hidden_layer():
    g = [[0] * W for _ in range(H)]
    for x in range(2, W - 2, 3):
        g[2][x] = MEADOW + 12   # crates in the sky: hidden, never drawn
    return g


def front_layer():
    g = [[0] * W for _ in range(H)]
    for x in (4, 13, 14, 28, 40, 53, 54):
        g[H - ground_height(x) - 1][x] = MEADOW + 15  # tall grass in front of the creatures
    return g


def csv(grid):
    return "\n" + ",\n".join(",".join(str(v) for v in row) for row in grid) + "\n"


def tmx():
    layers = []
    layers.append(' <imagelayer id="1" name="Far hills" offsetx="0" offsety="192" parallaxx="0.4" parallaxy="0.8" repeatx="1">\n'
                  '  <image source="hills.png" width="512" height="160"/>\n </imagelayer>\n')
    layers.append(f' <layer id="2" name="Back" width="{W}" height="{H}" parallaxx="0.9">\n'
                  f'  <data encoding="csv">{csv(back_layer())}</data>\n </layer>\n')
    layers.append(' <group id="3" name="Terrain" opacity="0.95">\n'
                  f'  <layer id="4" name="Ground" width="{W}" height="{H}">\n'
                  f'   <data encoding="csv">{csv(ground_layer())}</data>\n  </layer>\n'
                  f'  <layer id="5" name="Crystals" width="{W}" height="{H}">\n'
                  f'   <data encoding="csv">{csv(cave_layer())}</data>\n  </layer>\n'
                  ' </group>\n')
    layers.append(f' <layer id="6" name="Props" width="{W}" height="{H}" offsetx="0" offsety="4">\n'
                  f'  <data encoding="csv">{csv(props_layer())}</data>\n </layer>\n')
    layers.append(f' <layer id="7" name="Hidden" width="{W}" height="{H}" visible="0">\n'
                  f'  <data encoding="csv">{csv(hidden_layer())}</data>\n </layer>\n')
    layers.append(f' <layer id="8" name="Front grass" width="{W}" height="{H}" opacity="0.85" tintcolor="#ffc8e6a0">\n'
                  '  <properties>\n   <property name="foreground" type="bool" value="true"/>\n  </properties>\n'
                  f'  <data encoding="csv">{csv(front_layer())}</data>\n </layer>\n')
    layers.append(' <objectgroup id="9" name="Objects">\n'
                  f'  <object id="1" name="spawn" type="spawn" x="192" y="{(H - 3) * 32}">\n   <point/>\n  </object>\n'
                  ' </objectgroup>\n')
    return ('<?xml version="1.0" encoding="UTF-8"?>\n'
            f'<map version="1.8" tiledversion="1.8.2" orientation="orthogonal" renderorder="right-down" width="{W}" height="{H}" '
            'tilewidth="32" tileheight="32" infinite="0" backgroundcolor="#a6cfe8" nextlayerid="10" nextobjectid="2">\n'
            ' <properties>\n  <property name="pixels_per_metre" type="float" value="64"/>\n </properties>\n'
            f' <tileset firstgid="{MEADOW}" source="meadow.tsx"/>\n'
            f' <tileset firstgid="{CAVE}" name="cave" tilewidth="16" tileheight="16" tilecount="32" columns="8">\n'
            '  <image source="cave.png" width="128" height="64"/>\n </tileset>\n'
            f' <tileset firstgid="{PROPS}" source="props.tsj"/>\n'
            + "".join(layers) + '</map>\n')


def tsx():
    solid = [0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 16, 17, 24, 25, 26, 27]
    tiles = "".join(f'  <tile id="{i}">\n   <properties>\n    <property name="collider" type="bool" value="true"/>\n'
                    '   </properties>\n  </tile>\n' for i in solid)
    return ('<?xml version="1.0" encoding="UTF-8"?>\n'
            '<tileset version="1.8" tiledversion="1.8.2" name="meadow" tilewidth="32" tileheight="32" tilecount="32" columns="8">\n'
            ' <image source="meadow.png" width="256" height="128"/>\n' + tiles + '</tileset>\n')


def props_tsj():
    images = [("tree", 64, 96), ("bush", 48, 32), ("rock", 40, 24), ("signpost", 32, 48)]
    return {
        "columns": 0, "grid": {"height": 1, "orientation": "orthogonal", "width": 1}, "margin": 0,
        "name": "props", "spacing": 0, "tilecount": len(images), "tiledversion": "1.8.2",
        "tileheight": 96, "tilewidth": 64, "type": "tileset", "version": "1.8",
        "tiles": [{"id": i, "image": f"props/{n}.png", "imagewidth": w, "imageheight": h}
                  for i, (n, w, h) in enumerate(images)],
    }


# ---- canyon.ldtk ---------------------------------------------------------------------------------

CW, CH, G = 40, 16, 16


def canyon_height(x):
    if x < 2 or x >= CW - 2:
        return 12
    if 14 <= x <= 19:
        return 6
    if 26 <= x <= 28:
        return 2
    return 4


def canyon():
    intgrid = []
    solid = [[False] * CW for _ in range(CH)]
    for y in range(CH):
        for x in range(CW):
            v = 1 if y >= CH - canyon_height(x) else 0
            solid[y][x] = v == 1
            intgrid.append(v)
    # A ladder (IntGrid value 2: passable) up the step at x 13.
    for y in range(CH - 6, CH - 4):
        intgrid[y * CW + 13] = 2

    def is_solid(x, y):
        return 0 <= x < CW and 0 <= y < CH and solid[y][x]

    auto = []   # the auto-layer tiles of the IntGrid layer
    for y in range(CH):
        for x in range(CW):
            if not solid[y][x]:
                continue
            top = not is_solid(x, y - 1)
            lo = not is_solid(x - 1, y) and x > 0
            ro = not is_solid(x + 1, y) and x < CW - 1
            if top:
                t, f = (1, 0) if lo and not ro else (1, 1) if ro and not lo else (0, 0)
            elif lo:
                t, f = 4, 0
            elif ro:
                t, f = 4, 1           # the right side: the left side mirrored
            else:
                t, f = (6 if (x * 5 + y * 3) % 13 == 0 else 3 if y < CH - 3 else 7), 0
            auto.append({"px": [x * G, y * G], "src": [(t % 8) * G, (t // 8) * G], "f": f, "t": t, "d": [y * CW + x], "a": 1})

    wall = [{"px": [x * G, y * G], "src": [(12 + (x + y) % 2) * G, G], "f": 0, "t": 12 + (x + y) % 2, "d": [y * CW + x], "a": 1}
            for y in range(CH) for x in range(CW) if not solid[y][x] and y > 3]

    def ground_y(x):
        return (CH - canyon_height(x)) * G

    decor = []
    for x, t, f in ((6, 10, 0), (9, 11, 0), (22, 10, 1), (33, 9, 0), (35, 10, 0)):
        y = ground_y(x) - G if t != 11 else 2 * G
        decor.append({"px": [x * G, y], "src": [(t % 8) * G, (t // 8) * G], "f": f, "t": t, "d": [(y // G) * CW + x]})
    decor.append({"px": [10 * G, 6 * G], "src": [14 % 8 * G, G], "f": 0, "t": 14, "d": [6 * CW + 10]})
    decor.append({"px": [11 * G, 6 * G], "src": [14 % 8 * G, G], "f": 1, "t": 14, "d": [6 * CW + 11]})
    decor.append({"px": [9 * G, 3 * G], "src": [7 * G, G], "f": 0, "t": 15, "d": [3 * CW + 9]})
    # Stalactites hanging in front (the Foreground layer), one flipped upside down into a stalagmite.
    front = [{"px": [x * G, 0], "src": [0, G], "f": 0, "t": 8, "d": [x]} for x in (4, 5, 21, 30, 31)]
    front.append({"px": [24 * G, ground_y(24) - G], "src": [0, G], "f": 2, "t": 8, "d": [0]})

    def layer_def(uid, ident, typ, extra=None):
        d = {"__type": typ, "identifier": ident, "type": typ, "uid": uid, "gridSize": G, "displayOpacity": 1,
             "pxOffsetX": 0, "pxOffsetY": 0, "parallaxFactorX": 0, "parallaxFactorY": 0, "parallaxScaling": True,
             "intGridValues": [], "tilesetDefUid": 1 if typ != "Entities" else None}
        d.update(extra or {})
        return d

    def layer_inst(ident, typ, uid, grid_tiles=None, auto_tiles=None, intgrid_csv=None, entities=None, opacity=1):
        return {"__identifier": ident, "__type": typ, "__cWid": CW, "__cHei": CH, "__gridSize": G, "__opacity": opacity,
                "__pxTotalOffsetX": 0, "__pxTotalOffsetY": 0,
                "__tilesetDefUid": None if typ == "Entities" else 1,
                "__tilesetRelPath": None if typ == "Entities" else "cave.png",
                "iid": f"layer-{uid}", "levelId": 0, "layerDefUid": uid, "pxOffsetX": 0, "pxOffsetY": 0, "visible": True,
                "optionalRules": [], "intGridCsv": intgrid_csv or [], "autoLayerTiles": auto_tiles or [],
                "seed": 1, "overrideTilesetUid": None, "gridTiles": grid_tiles or [], "entityInstances": entities or []}

    player = {"__identifier": "Player", "__grid": [4, CH - 5], "__pivot": [0.5, 1], "__tags": [], "__tile": None,
              "__smartColor": "#BE4A2F", "iid": "player", "width": 16, "height": 32, "defUid": 20,
              "px": [4 * G + 8, ground_y(4)], "fieldInstances": []}
    level = {
        "identifier": "Canyon", "iid": "level-canyon", "uid": 0, "worldX": 0, "worldY": 0, "worldDepth": 0,
        "pxWid": CW * G, "pxHei": CH * G, "__bgColor": "#2b2838", "bgColor": "#2b2838", "useAutoIdentifier": False,
        "bgRelPath": "hills.png", "bgPos": "Unscaled", "bgPivotX": 0, "bgPivotY": 0,
        "__bgPos": {"topLeftPx": [0, 48], "scale": [1, 1], "cropRect": [0, 0, 512, 160]},
        "__smartColor": "#8E8B99", "externalRelPath": None, "fieldInstances": [], "__neighbours": [],
        "layerInstances": [
            layer_inst("Entities", "Entities", 14, entities=[player]),
            layer_inst("Foreground", "Tiles", 15, grid_tiles=front),
            layer_inst("Decor", "Tiles", 12, grid_tiles=decor),
            layer_inst("Collisions", "IntGrid", 11, auto_tiles=auto, intgrid_csv=intgrid),
            layer_inst("Wall", "AutoLayer", 13, auto_tiles=wall, opacity=0.6),
        ],
    }
    return {
        "__header__": {"fileType": "LDtk Project JSON", "app": "LDtk", "doc": "https://ldtk.io/json",
                       "schema": "https://ldtk.io/files/JSON_SCHEMA.json", "appAuthor": "Sebastien 'deepnight' Benard",
                       "appVersion": "1.3.3", "url": "https://ldtk.io"},
        "iid": "canyon-project", "jsonVersion": "1.3.3", "appBuildId": 1, "nextUid": 30,
        "identifierStyle": "Capitalize", "worldLayout": "Free", "worldGridWidth": 256, "worldGridHeight": 256,
        "defaultLevelWidth": CW * G, "defaultLevelHeight": CH * G, "defaultPivotX": 0, "defaultPivotY": 0,
        "defaultGridSize": G, "bgColor": "#40465B", "defaultLevelBgColor": "#2b2838", "externalLevels": False,
        "defs": {
            "layers": [
                layer_def(14, "Entities", "Entities"),
                layer_def(15, "Foreground", "Tiles"),
                layer_def(12, "Decor", "Tiles"),
                layer_def(11, "Collisions", "IntGrid", {"intGridValues": [
                    {"value": 1, "identifier": "stone", "color": "#5A5668", "tile": None},
                    {"value": 2, "identifier": "ladder", "color": "#B07B46", "tile": None}]}),
                layer_def(13, "Wall", "AutoLayer", {"parallaxFactorX": 0.2, "parallaxFactorY": 0.2}),
            ],
            "entities": [{"identifier": "Player", "uid": 20, "width": 16, "height": 32, "pivotX": 0.5, "pivotY": 1}],
            "tilesets": [{"__cWid": 8, "__cHei": 4, "identifier": "Cave", "uid": 1, "relPath": "cave.png", "pxWid": 128,
                          "pxHei": 64, "tileGridSize": G, "spacing": 0, "padding": 0, "tags": [], "enumTags": [],
                          "customData": [], "savedSelections": [], "cachedPixelData": None, "embedAtlas": None,
                          "tagsSourceEnumUid": None}],
            "enums": [], "externalEnums": [], "levelFields": [],
        },
        "levels": [level],
        "worlds": [], "toc": [],
    }


def main():
    with open(os.path.join(HERE, "meadow.tmx"), "w") as f:
        f.write(tmx())
    with open(os.path.join(HERE, "meadow.tsx"), "w") as f:
        f.write(tsx())
    with open(os.path.join(HERE, "props.tsj"), "w") as f:
        json.dump(props_tsj(), f, indent=1)
        f.write("\n")
    with open(os.path.join(HERE, "canyon.ldtk"), "w") as f:
        json.dump(canyon(), f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    main()
