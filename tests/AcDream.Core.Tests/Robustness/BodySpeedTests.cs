using System.Numerics;
using AcDream.Core.Dat;
using AcDream.Core.Physics;
using AcDream.Testing;

namespace AcDream.Core.Tests.Robustness;

/// <summary>
/// Fast movers into walls: 1, 5, 10, 20 and 50 m/s at 30 Hz and 10 Hz (up to 5 m per call), into a
/// room's walls and into a partition of zero thickness that closes off half the room
/// (<see cref="BodyCourses.Kind.Partition"/>), in both world frames: no call ends overlapping a wall by
/// more than 1 mm, and none passes through one.
/// </summary>
public class BodySpeedTests
{
    private const float Step = 0.5f;

    public static TheoryData<int, int> Speeds()
    {
        var data = new TheoryData<int, int>();
        foreach (int hz in new[] { 30, 10 })
        {
            foreach (int speed in new[] { 1, 5, 10, 20, 50 })
            {
                data.Add(speed, hz);
            }
        }

        return data;
    }

    [Theory]
    [MemberData(nameof(Speeds))]
    public void Resolve_FastIntoWallsAndThinWalls_NeverOverlapsNorTunnels(int speed, int hz)
    {
        var random = new Random((speed * 100) + hz);
        float length = (float)speed / hz;
        int calls = 0, atWalls = 0;
        double worstOverlap = double.NegativeInfinity;
        for (int c = 0; c < 16; c++)
        {
            int lb = c % 4 == 0 ? 0xFE : random.Next(1, 254);
            BodyCourse course = BodyCourses.Build(BodyCourses.Kind.Partition, random, lb, random.Next(1, 254), global: c % 2 == 0);
            float partition = course.Areas[0].Max.X;
            MoverBody body = c % 3 == 0 ? new MoverBody(BodyCourses.Range(random, 0.2f, 0.6f), 1.8f) : MoverBody.Player;
            MovementOptions options = c % 2 == 0 ? new MovementOptions { Body = body } : MovementOptions.Player with { Body = body };
            Frame cellFrame = course.Areas[0].Frame;
            for (int walk = 0; walk < 3; walk++)
            {
                (Vector3 pos, uint cell) = course.RandomStart(random, body, Step, 0.01f)!.Value;
                // Aimed east (at the partition) or at a random wall, up to 75° off the wall's normal; walked 6 m or 1 s.
                float yaw = walk == 0 ? 0f : random.Next(4) * MathF.PI / 2;
                float aim = yaw + BodyCourses.Range(random, -1.3f, 1.3f);
                Vector3 direction = Vector3.Transform(new Vector3(MathF.Cos(aim), MathF.Sin(aim), 0), cellFrame.Orientation);
                var delta = new Vector3(direction.X, direction.Y, 0) * length;
                for (int f = 0; f < Math.Max(hz, hz * 6 / speed); f++)
                {
                    BodyCall call = BodyCheck.Compare(course, pos, cell, delta, Step, options);
                    call.Overlap.Should().BeLessThanOrEqualTo(BodyCheck.OverlapLimit, $"{speed} m/s at {hz} Hz, frame {f}: {call}");
                    call.Tunnelled.Should().BeFalse($"{speed} m/s at {hz} Hz, frame {f}: {call}");
                    float x = course.CellLocal(cellFrame, call.Engine.Position).X;
                    x.Should().BeLessThan(partition, $"{speed} m/s at {hz} Hz, frame {f}: through the partition: {call}");
                    calls++;
                    atWalls += call.Engine.Outcome is ResolveOutcome.Slid or ResolveOutcome.Wall ? 1 : 0;
                    worstOverlap = Math.Max(worstOverlap, call.Overlap);
                    (pos, cell) = (call.Engine.Position, call.Engine.CellId);
                }
            }
        }

        atWalls.Should().BeGreaterThan(calls / 3, $"{speed} m/s at {hz} Hz: most calls meet a wall ({atWalls} of {calls}; worst overlap {worstOverlap:E2} m)");
    }
}
