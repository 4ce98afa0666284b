using System.Numerics;
using AcDream.Core.Physics;
using QuickStart;

// Landblock 0xA9B4 (Holtburg) as the dat holds it; map each record 1:1 to the engine's surfaces.
HoltburgDat dat = HoltburgDat.Read();
var engine = new PhysicsEngine(centerLandblockId: 0xA9B4FFFFu);  // world (0, 0) = the south-west corner of 0xA9B4
var terrain = new TerrainSurface(dat.LandBlock.Height, dat.HeightTable, 0xA9B4FFFFu);
var cells = dat.EnvCells.Select(c => new CellSurface(c.Id, c, dat.CellStructOf(c))).ToList();
var objects = ObjectSurface.FromLandblock(0xA9B4FFFFu, dat.LandBlockInfo, dat.EnvCells, dat.GfxObjs, dat.Setups);
engine.AddLandblock(0xA9B4FFFFu, terrain, cells, objects);

// A player: the game's body, step, gravity and jump (the defaults of CharacterSettings), west of the cottage.
var player = new Character(engine, new CharacterSettings(), new Vector3(128f, 5.6f, 94f), cellId: 0);

// Walk at 2 m/s over the terrain, in by the west door, down the cellar stair and back up it; then jump under the ceiling.
(string Leg, Vector2 To, bool Jump)[] route =
[
    ("over the terrain", new(134.0f, 5.6f), false),
    ("in by the west door", new(139.2f, 6.2f), false),
    ("to the cellar stair", new(141.3f, 6.2f), false),
    ("down into the cellar", new(141.3f, 10.5f), false),
    ("up the stair", new(141.3f, 6.2f), false),
    ("into the main room", new(138.5f, 6.0f), false),
    ("a jump under the ceiling", new(138.5f, 6.0f), true),
];
int frame = 0;
foreach ((string leg, Vector2 to, bool jump) in route)
{
    for (int i = 0; i < 200; i++, frame++)
    {
        Vector2 away = to - new Vector2(player.Position.X, player.Position.Y);
        Vector2 velocity = away.Length() > 0.05f ? Vector2.Normalize(away) * 2f : Vector2.Zero;
        CharacterStep step = player.Update(1f / 30f, velocity, jump: jump && i == 0);
        Console.WriteLine(
            $"{frame,4}  {leg,-25} ({step.Position.X:F3}, {step.Position.Y:F3}, {step.Position.Z:F3})  cell 0x{step.CellId:X8}  "
            + $"{(step.IsOnGround ? "ground" : "air   ")}  vz {step.VerticalSpeed,6:F2}{(step.HeadHit ? "  head hit" : "")}{(step.Landed ? "  landed" : "")}");
        if (velocity == Vector2.Zero && step.IsOnGround && !(jump && i == 0))
        {
            break; // there, standing
        }
    }
}
