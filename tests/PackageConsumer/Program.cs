// A consumer of the AcDream.Core package: one flat landblock, one step east and one ray down, the answers printed.
// Exits 1 when an answer is not the obvious one (on the ground, at the flat height, moved 1 m east; the ray meets the
// terrain at the flat height).
using System.Numerics;
using AcDream.Core.Physics;

const uint landblock = 0xA9B4FFFFu;
const float groundZ = 20f;

var heightTable = new float[256];
for (int i = 0; i < heightTable.Length; i++)
    heightTable[i] = i * 2f;
var heights = new byte[81];               // 9 × 9 vertices, every one at table index 10: Z = 20 m
Array.Fill(heights, (byte)10);

var engine = new PhysicsEngine(centerLandblockId: landblock); // world (0,0) = SW corner of 0xA9B4
engine.AddLandblock(landblock, new TerrainSurface(heights, heightTable, landblock), []);

var start = new Vector3(96f, 96f, groundZ);
uint startCell = (landblock & 0xFFFF0000u) | (4u * 8u + 4u + 1u); // outdoor cell (4, 4)
ResolveResult r = engine.Resolve(start, startCell, delta: new Vector3(1f, 0f, 0f), stepUpHeight: 0.5f);

Console.WriteLine(FormattableString.Invariant(
    $"Resolve: position ({r.Position.X:F3}, {r.Position.Y:F3}, {r.Position.Z:F3}), cell 0x{r.CellId:X8}, on ground {r.IsOnGround}"));

CastHit down = engine.Cast(new CastRequest(start + new Vector3(0f, 0f, 5f), startCell, new Vector3(0f, 0f, -10f)));
Console.WriteLine(FormattableString.Invariant(
    $"Cast: {down.Kind} at ({down.Point.X:F3}, {down.Point.Y:F3}, {down.Point.Z:F3}), fraction {down.Fraction:F3}"));

bool ok = down.Hit && down.Kind == SurfaceKind.Terrain && Math.Abs(down.Point.Z - groundZ) < 1e-3f
    && r.IsOnGround
    && Math.Abs(r.Position.Z - groundZ) < 1e-3f
    && Math.Abs(r.Position.X - 97f) < 1e-3f
    && Math.Abs(r.Position.Y - 96f) < 1e-3f
    && r.CellId == startCell;
if (!ok)
    Console.Error.WriteLine("unexpected answer from the packaged engine");
return ok ? 0 : 1;
