namespace AcDream.Core.Benchmarks.Compare;

/// <summary>The median of a sample and a 95 % bootstrap interval of it (2,000 resamples, a fixed seed).</summary>
internal static class Statistics
{
    public static double Median(double[] values)
    {
        var sorted = (double[])values.Clone();
        Array.Sort(sorted);
        int n = sorted.Length;
        return n % 2 == 1 ? sorted[n / 2] : (sorted[(n / 2) - 1] + sorted[n / 2]) / 2;
    }

    public static (double Low, double High) MedianInterval(double[] values)
    {
        const int Resamples = 2000;
        var random = new Random(1);
        var medians = new double[Resamples];
        var sample = new double[values.Length];
        for (int k = 0; k < Resamples; k++)
        {
            for (int i = 0; i < sample.Length; i++)
            {
                sample[i] = values[random.Next(values.Length)];
            }

            medians[k] = Median(sample);
        }

        Array.Sort(medians);
        return (medians[(int)(Resamples * 0.025)], medians[(int)(Resamples * 0.975) - 1]);
    }
}
