using System.Numerics;
using AcDream.Core.Dat;
using AcDream.Core.Physics;
using Xunit.Abstractions;

namespace AcDream.Core.Tests.Robustness;

/// <summary>
/// The one-bit skip against the fine grid itself, at the coordinates where it could go wrong: starts on
/// a cell's edge (24 k m), one float step either side of it, at 0 and 192 m, and moves just short of
/// <see cref="LandblockEntry.ObjectCellReach"/> along each axis and diagonally. Wherever a start's cell
/// bit is clear, the fine grid (<c>LandblockEntry.Objects</c>) must list no object over the
/// move's box; trees are seeded at random, many landblocks over.
/// </summary>
public class ObjectCellBitTests(ITestOutputHelper output)
{
    [Fact]
    public void A_clear_bit_means_no_object_is_listed_over_a_short_moves_box()
    {
        (Setup tree, Dictionary<uint, GfxObj> parts) = ObjectKit.Tree(0.3f, 4f);
        var coordinates = new List<float>();
        for (int k = 0; k <= PhysicsConstants.CellsPerSide; k++)
        {
            float edge = k * PhysicsConstants.CellSize;
            coordinates.AddRange([MathF.BitDecrement(edge), edge, MathF.BitIncrement(edge), edge + 12f]);
        }

        coordinates.RemoveAll(c => c < 0f || c > PhysicsConstants.LandblockSize);
        float r = MathF.BitDecrement(LandblockEntry.ObjectCellReach);
        Vector2[] deltas = [new(r, 0f), new(-r, 0f), new(0f, r), new(0f, -r), new(r, r), new(-r, r), new(r, -r), new(-r, -r)];
        var random = new Random(15);
        int skipped = 0, checkedMoves = 0;
        for (int landblock = 0; landblock < 40; landblock++)
        {
            var objects = new ObjectSurface[1 + random.Next(6)];
            for (int i = 0; i < objects.Length; i++)
            {
                var at = new Vector2((float)(random.NextDouble() * PhysicsConstants.LandblockSize), (float)(random.NextDouble() * PhysicsConstants.LandblockSize));
                objects[i] = new ObjectSurface(tree, parts, ObjectKit.At(new Vector3(at, 10f), 0f), 0);
            }

            var entry = new LandblockEntry(0x4C, 0x5D, TestData.FlatTerrain(10f, 0x4C5DFFFF), [], objects);
            foreach (float x in coordinates)
            {
                foreach (float y in coordinates)
                {
                    var start = new Vector2(x, y);
                    bool bit = (entry.ObjectCells & (1UL << (int)(CellIds.OutdoorCellNumber(x, y) - 1))) != 0;
                    foreach (Vector2 d in deltas)
                    {
                        checkedMoves++;
                        if (!bit)
                        {
                            skipped++;
                            entry.Objects.ListsAny(Vector2.Min(start, start + d) - new Vector2(PhysicsConstants.NearMargin), Vector2.Max(start, start + d) + new Vector2(PhysicsConstants.NearMargin)).Should().BeFalse(
                                $"landblock {landblock}: from {start:R} by {d:R}, cell {CellIds.OutdoorCellNumber(x, y)} clear, objects at {string.Join(", ", objects.Select(o => o.BoundsMin))}");
                            entry.ObjectsMayBeWithin(start, r).Should().BeFalse($"from {start:R}");
                        }
                    }
                }
            }
        }

        output.WriteLine($"{checkedMoves} moves, {skipped} from a clear cell");
        skipped.Should().BeGreaterThan(checkedMoves / 4);
        (checkedMoves - skipped).Should().BeGreaterThan(checkedMoves / 20);
    }
}
